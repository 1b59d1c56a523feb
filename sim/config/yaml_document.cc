#include "sim/config/yaml_document.h"

#include <vector>

#include "sim/config/config_error.h"

namespace plywood::sim {

YAML::Node LoadOneYamlDocument(const std::string& text, const std::string& source) {
  std::vector<YAML::Node> documents;
  try {
    documents = YAML::LoadAll(text);
  } catch (const YAML::Exception& e) {
    // yaml-cpp's own text carries the line and column.
    throw ConfigError(source, "", std::string("not valid YAML: ") + e.what());
  }
  for (std::size_t i = 1; i < documents.size(); ++i) {
    if (documents[i].IsNull()) continue;
    throw ConfigError(source, "line " + std::to_string(documents[i].Mark().line + 1),
                      "a second YAML document begins here (after a '---' line), which would be "
                      "ignored: only the first document is read; write the file as one document");
  }
  return documents.empty() ? YAML::Node() : documents.front();
}

YAML::Node CopyWithoutSharedNodes(const YAML::Node& node) {
  YAML::Node copy;
  switch (node.Type()) {
    case YAML::NodeType::Undefined:
      return copy;
    case YAML::NodeType::Null:
      copy = YAML::Node(YAML::NodeType::Null);
      break;
    case YAML::NodeType::Scalar:
      copy = YAML::Node(node.Scalar());
      break;
    case YAML::NodeType::Sequence:
      copy = YAML::Node(YAML::NodeType::Sequence);
      for (const YAML::Node& element : node) copy.push_back(CopyWithoutSharedNodes(element));
      break;
    case YAML::NodeType::Map:
      copy = YAML::Node(YAML::NodeType::Map);
      for (const auto& entry : node) {
        copy.force_insert(CopyWithoutSharedNodes(entry.first),
                          CopyWithoutSharedNodes(entry.second));
      }
      break;
  }
  copy.SetTag(node.Tag());
  copy.SetStyle(node.Style());  // flow or block, as written: config.yaml may emit it
  return copy;
}

}  // namespace plywood::sim
