#include "sim/config/geometric_map_config.h"

#include <cmath>
#include <stdexcept>

#include "sim/config/config_archive.h"
#include "sim/config/geometric_map_fields.h"
#include "sim/config/require_field.h"
#include "sim/config/yaml_fields.h"

namespace plywood::sim {

using perception::VisitFields;

void GeometricMapConfig::Validate() const {
  RequireField(max_sonar_age_s >= 0.0 && max_sonar_age_s <= 10.0, "max_sonar_age_s",
               "must be in [0, 10]", max_sonar_age_s);
}

void ReadGeometricMapConfig(YamlFields fields, GeometricMapConfig& config) {
  config.given = true;
  perception::GeometricMapOptions& o = config.options;
  ReadOptions(fields.Child("fusion"), o.fusion);
  ReadOptions(fields.Child("histograms"), o.histograms);
  ReadOptions(fields.Child("frame"), o.frame);
  ReadOptions(fields.Child("correction"), o.correction);
  ReadOptions(fields.Child("segmentation"), o.segmentation);
  ReadOptions(fields.Child("aggregation"), o.aggregation);
  fields.Get("max_sonar_age_s", &config.max_sonar_age_s);
  ReadOptions(fields.Child("scoring"), config.scoring);
  fields.Finish();
  fields.Validate(config);
}

YAML::Node WriteGeometricMapConfig(GeometricMapConfig& config) {
  YAML::Node node(YAML::NodeType::Map);
  perception::GeometricMapOptions& o = config.options;
  node["fusion"] = WriteOptions(o.fusion);
  node["histograms"] = WriteOptions(o.histograms);
  node["frame"] = WriteOptions(o.frame);
  node["correction"] = WriteOptions(o.correction);
  node["segmentation"] = WriteOptions(o.segmentation);
  node["aggregation"] = WriteOptions(o.aggregation);
  node["max_sonar_age_s"] = FormatNumber(config.max_sonar_age_s);
  node["scoring"] = WriteOptions(config.scoring);
  return node;
}

}  // namespace plywood::sim
