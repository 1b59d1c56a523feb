#include "sim/runner/build_id.h"

#include <elf.h>
#include <link.h>

#include <cstdint>
#include <cstring>
#include <nlohmann/json.hpp>

#include "sim/runner/run_directory.h"
#include "sim/runner/text_file.h"

namespace plywood::sim {
namespace {

// Notes are 4-byte aligned records: namesz, descsz, type, name (padded), desc (padded).
std::string BuildIdInNotes(const unsigned char* notes, std::size_t size) {
  const auto padded = [](std::uint32_t n) { return (n + 3u) & ~3u; };
  std::size_t at = 0;
  while (at + sizeof(ElfW(Nhdr)) <= size) {
    ElfW(Nhdr) header;
    std::memcpy(&header, notes + at, sizeof(header));
    const std::size_t name_at = at + sizeof(header);
    const std::size_t desc_at = name_at + padded(header.n_namesz);
    const std::size_t next = desc_at + padded(header.n_descsz);
    if (next > size) break;
    if (header.n_type == NT_GNU_BUILD_ID && header.n_namesz == 4 &&
        std::memcmp(notes + name_at, "GNU", 4) == 0) {
      static constexpr char kHex[] = "0123456789abcdef";
      std::string hex;
      for (std::uint32_t i = 0; i < header.n_descsz; ++i) {
        hex += kHex[notes[desc_at + i] >> 4];
        hex += kHex[notes[desc_at + i] & 15];
      }
      return hex;
    }
    at = next;
  }
  return "";
}

// dl_iterate_phdr visits the program itself first.
int FromProgramHeaders(dl_phdr_info* info, std::size_t, void* result) {
  auto* id = static_cast<std::string*>(result);
  for (int i = 0; i < info->dlpi_phnum && id->empty(); ++i) {
    const ElfW(Phdr)& segment = info->dlpi_phdr[i];
    if (segment.p_type != PT_NOTE) continue;
    *id = BuildIdInNotes(reinterpret_cast<const unsigned char*>(info->dlpi_addr + segment.p_vaddr),
                         segment.p_memsz);
  }
  return 1;  // only the program
}

}  // namespace

const std::string& ProgramBuildId() {
  static const std::string id = [] {
    std::string found;
    dl_iterate_phdr(FromProgramHeaders, &found);
    return found;
  }();
  return id;
}

std::string RunBuildId(const std::filesystem::path& run_dir) {
  try {
    const auto record = nlohmann::json::parse(ReadTextFile(run_dir / kRunCompleteFile));
    return record.value("plywood_build_id", std::string());
  } catch (const std::exception&) {
    return "";  // unreadable: WhyNotAFinishedRun says why
  }
}

}  // namespace plywood::sim
