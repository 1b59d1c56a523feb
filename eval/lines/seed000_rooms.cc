#include "eval/lines/seed000_rooms.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "msgs/shortest_number.h"
#include "perception/lines/round_objects_of_quiet_scan.h"
#include "perception/logs/regular_file.h"
#include "sim/config/config_error.h"
#include "sim/config/folder_behind_links.h"
#include "sim/config/robot_catalog.h"
#include "sim/config/yaml_fields.h"
#include "sim/runner/spawn_refused.h"

namespace plywood::eval {
namespace {

std::filesystem::path ResolveWorld(const std::string& text, const sim::ExperimentConfig& config,
                                   const sim::YamlFields& fields, const std::string& key) {
  const std::filesystem::path given(text);
  if (given.is_absolute()) {
    if (perception::IsRegularFile(given)) return given.lexically_normal();
  } else {
    const auto base = sim::FolderBehindLinks(config.source_file);
    for (const auto& root : {base, sim::DataRoot()}) {
      if (perception::IsRegularFile(root / given)) return (root / given).lexically_normal();
    }
  }
  fields.Fail(key, "no such file: " + text);
}

// What the spot's scans cannot give round objects from, or "" when they can: with one scan the
// "median" is that scan, its noise scaled up by 1.25; with median_of_scans the extractors already
// see the median, in which the round objects would be looked for with the noise scaled twice;
// with split_and_merge's round-object stage off, or its noise 0, nothing is found and no figure
// changes. `true` ran as if it could (s63); now it is refused, and `auto` stays off.
std::string WhyRoundObjectsFromScansCannotWork(const sim::ExperimentConfig& config,
                                               const Seed000RoomsOptions& options) {
  if (options.scans < 2) {
    return "needs the spot's other scans, but scans is " + std::to_string(options.scans) +
           ": the median of one scan is that scan (set scans: 2 or more, or "
           "round_objects_from_scans: false)";
  }
  if (options.median_of_scans) {
    return "cannot be combined with median_of_scans: the extractors then see the median scan "
           "itself, and the round objects would be looked for in a median of medians with its "
           "noise scaled down twice; set one of the two";
  }
  // With no noise no circle passes the round-object test (its residual over sigma^2), nor does a
  // line lie within 3 sigma of a rim: every figure was the off figure.
  const double sigma_m = config.lines.options.split_and_merge.breakpoints.sigma_m;
  if (!(sigma_m > 0.0)) {
    return "measures round objects against lines.split_and_merge.breakpoints.sigma_m, the "
           "scans' range noise, which is " +
           msgs::ShortestNumber(sigma_m) +
           ": no circle can pass, so it would change no figure; "
           "give the noise";
  }
  if (!config.lines.options.split_and_merge.round_objects.reject_round_objects) {
    return "finds round objects with split_and_merge's round-object stage, which "
           "lines.split_and_merge.reject_round_objects: false turns off, so it would change no "
           "figure; set one of the two";
  }
  return "";
}

void ReadRoundObjectsFromScans(const sim::ExperimentConfig& config, sim::YamlFields& fields,
                               Seed000RoomsOptions* options) {
  const std::string field = "round_objects_from_scans";
  if (fields.Has(field)) {
    const YAML::Node node = fields.Raw(field);
    if (!node.IsScalar()) {
      fields.Fail(field, std::string("expected true, false or auto, got ") +
                             (node.IsNull()       ? "nothing"
                              : node.IsSequence() ? "a list"
                                                  : "a mapping"));
    }
    const std::string mode = node.Scalar();
    // `!!str true` is the text "true", not the boolean: every true/false key refuses the tag
    // (sim/config/yaml_fields.cc), and this one did until it also took auto (s65 review).
    if (node.Tag() == "tag:yaml.org,2002:str" && (mode == "true" || mode == "false")) {
      fields.Fail(field,
                  "the YAML tag '!!str' says a string, but true and false are the key's "
                  "booleans (written '" +
                      mode + "'): drop the tag");
    }
    using Mode = Seed000RoomsOptions::SpotRoundObjects;
    if (mode == "true") {
      options->round_objects_mode = Mode::kOn;
    } else if (mode == "false") {
      options->round_objects_mode = Mode::kOff;
    } else if (mode == "auto") {
      options->round_objects_mode = Mode::kAuto;
    } else {
      fields.Fail(field, "expected true, false or auto, got '" + mode + "'");
    }
  }
  if (options->round_objects_mode == Seed000RoomsOptions::SpotRoundObjects::kOff) return;
  const std::string why_not = WhyRoundObjectsFromScansCannotWork(config, *options);
  if (options->round_objects_mode == Seed000RoomsOptions::SpotRoundObjects::kOn &&
      !why_not.empty()) {
    fields.Fail(field, why_not);
  }
  options->round_objects_from_scans = why_not.empty();
}

}  // namespace

Seed000RoomsOptions ReadSeed000RoomsOptions(const sim::ExperimentConfig& config) {
  Seed000RoomsOptions options;
  sim::YamlFields fields(config.protocol_options, config.source_file, config.protocol);
  fields.Get("scans", &options.scans);
  if (options.scans < 1 || options.scans > 1000) {
    fields.Fail("scans", "must be in 1..1000, got " + std::to_string(options.scans));
  }
  fields.Get("range_cut_m", &options.range_cut_m);
  if (!(options.range_cut_m > 0.0)) fields.Fail("range_cut_m", "must be > 0");
  fields.Get("rig_at", &options.rig_at);
  fields.Get("median_of_scans", &options.median_of_scans);
  ReadRoundObjectsFromScans(config, fields, &options);
  if (options.rig_at != "origin" && options.rig_at != "spawn") {
    fields.Fail("rig_at", "expected origin or spawn, got '" + options.rig_at + "'");
  }
  std::vector<sim::YamlFields> rooms = fields.ChildList("rooms");
  for (std::size_t i = 0; i < rooms.size(); ++i) {
    Seed000Room room;
    if (!rooms[i].Has("world")) rooms[i].Fail("world", "missing: give the room's MJCF file");
    rooms[i].Get("world", &room.world);
    room.world_path = ResolveWorld(room.world, config, rooms[i], "world");
    rooms[i].Get("range_cut_m", &room.range_cut_m);
    if (!(room.range_cut_m > 0.0)) rooms[i].Fail("range_cut_m", "must be > 0");
    rooms[i].Get("paper_lines", &room.paper_lines);
    if (room.paper_lines < 0) {
      rooms[i].Fail("paper_lines", "must be >= 0 (0: no figure from the paper), got " +
                                       std::to_string(room.paper_lines));
    }
    // Each room's figures are keyed by its world's name (metrics.json's seed000.NAME, the rows of
    // rooms.csv, lines.csv and walls.csv, NAME.png): a room listed twice kept only its second
    // entry's figures in metrics.json, beside rooms.csv rows of one name and both entries' scans
    // pooled in the totals (s63).
    for (std::size_t j = 0; j < i; ++j) {
      if (options.rooms[j].world_path.stem() == room.world_path.stem()) {
        rooms[i].Fail("world", "'" + room.world + "' has the name '" +
                                   room.world_path.stem().string() + "' of rooms[" +
                                   std::to_string(j) + "]'s world ('" + options.rooms[j].world +
                                   "'): each room's figures, rows and picture are keyed by that "
                                   "name, so the two would be mixed; list each room once, under "
                                   "a name of its own");
      }
    }
    rooms[i].Finish();
    options.rooms.push_back(room);
  }
  fields.Finish();
  return options;
}

namespace {

// The listed rooms run at their own cuts: a --set of the top-level range_cut_m (or a sweep axis of
// it) would change nothing, and a sweep would label identical cells differently (s55; it ran as
// if unset). The file's own top-level value is the default for other worlds, never refused.
std::vector<Seed000Room> RefuseASetCutTheRoomsIgnore(const sim::ExperimentConfig& config,
                                                     std::vector<Seed000Room> rooms) {
  const std::string key = config.protocol + ".range_cut_m";
  if (std::find(config.set_keys.begin(), config.set_keys.end(), key) == config.set_keys.end()) {
    return rooms;
  }
  std::string cuts;
  for (const Seed000Room& room : rooms) {
    cuts += (cuts.empty() ? "" : ", ") + msgs::ShortestNumber(room.range_cut_m);
  }
  throw sim::ConfigError(
      config.source_file, key,
      "set on the command line, it changes nothing: the world " +
          config.world_path.filename().string() + " is listed in " + config.protocol +
          ".rooms, and the listed rooms run at their own range_cut_m (" + cuts +
          "); edit their entries in rooms:, or run a world outside the list (--set world=PATH)");
}

}  // namespace

std::vector<Seed000Room> RoomsToRun(const sim::ExperimentConfig& config,
                                    const Seed000RoomsOptions& options) {
  if (!options.rooms.empty() &&
      std::filesystem::equivalent(options.rooms.front().world_path, config.world_path)) {
    return RefuseASetCutTheRoomsIgnore(config, options.rooms);
  }
  // A later room's world (--set world=worlds/seed000_room_2.xml) runs alone, but as its entry says
  // (its range cut and paper line count), not with the top-level range_cut_m meant for other
  // worlds.
  for (const Seed000Room& room : options.rooms) {
    if (std::filesystem::equivalent(room.world_path, config.world_path)) {
      return RefuseASetCutTheRoomsIgnore(config, {room});
    }
  }
  // A rooms list given on the command line that holds not the world runs none of its rooms: the
  // run would be the world's alone, at the top-level cut, as if the --set were not given (s63).
  const std::string rooms_key = config.protocol + ".rooms";
  for (const std::string& key : config.set_keys) {
    if (key == rooms_key || key.rfind(rooms_key + "[", 0) == 0 ||
        key.rfind(rooms_key + ".", 0) == 0) {
      throw sim::ConfigError(
          config.source_file, rooms_key,
          "set on the command line, it changes nothing: no room of it has the world " +
              config.world_path.filename().string() +
              ", and the rooms run only when the world is the first room's (a listed world runs "
              "that room alone); give --set world= the room to run, or list the world");
    }
  }
  Seed000Room user;
  user.world = config.world;
  user.world_path = config.world_path;
  user.range_cut_m = options.range_cut_m;
  if (options.rig_at == "spawn") {
    user.rig_W = {config.spawn.x_m, config.spawn.y_m};
    user.rig_theta_deg = config.spawn.theta_deg;
    user.rig_at_spawn = true;
  }
  return {user};
}

double Seed000RoomResult::WallsVisible() const {
  if (scores.empty() || scores.front().score.scans == 0) return 0.0;
  return static_cast<double>(scores.front().score.observable) /
         static_cast<double>(scores.front().score.scans);
}

double Seed000RoomResult::PointsPerScan() const {
  if (rig.front.empty() || rig.back.empty()) return 0.0;
  return static_cast<double>(rig.front[0].scan.ranges_m.size() + rig.back[0].scan.ranges_m.size());
}

namespace {

// Every record's ranges replaced by the per-beam median of the returns over all records (no return
// when fewer than half returned).
void MedianOfScans(std::vector<sim::LaserRecord>* records) {
  if (records->empty()) return;
  const std::size_t beams = records->front().scan.ranges_m.size();
  const double range_max_m = records->front().scan.range_max_m;
  std::vector<double> median(beams, range_max_m);
  std::vector<double> returns;
  for (std::size_t b = 0; b < beams; ++b) {
    returns.clear();
    for (const auto& record : *records)
      if (record.scan.ranges_m[b] < range_max_m) returns.push_back(record.scan.ranges_m[b]);
    if (2 * returns.size() < records->size()) continue;
    std::sort(returns.begin(), returns.end());
    const std::size_t k = returns.size();
    median[b] = k % 2 == 1 ? returns[k / 2] : 0.5 * (returns[k / 2 - 1] + returns[k / 2]);
  }
  for (auto& record : *records) record.scan.ranges_m = median;
}

// The round objects of the rig's spot, found in the per-beam median of its scans
// (perception::RoundObjectsOfQuietScan) with split_and_merge's options, its noise sigma scaled to
// the median's: the median of n Gaussian draws has 1.25 sigma / sqrt(n).
KnownRoundObjects RoundObjectsOfMedianScan(const BackToBackScans& rig, double range_cut_m,
                                           const sim::LinesConfig& lines) {
  BackToBackScans median = rig;
  MedianOfScans(&median.front);
  MedianOfScans(&median.back);
  KnownRoundObjects known;
  perception::SplitAndMergeOptions quiet = lines.options.split_and_merge;
  known.noise_sigma_m = quiet.breakpoints.sigma_m;
  const std::vector<TruthScan> scans = MakeTruthScans(median, range_cut_m);
  if (scans.empty()) return known;
  quiet.breakpoints.sigma_m *= 1.2533 / std::sqrt(static_cast<double>(rig.front.size()));
  known.circles = perception::RoundObjectsOfQuietScan(scans.front().points, quiet);
  return known;
}

}  // namespace

Seed000RoomResult RunSeed000Room(const sim::ExperimentConfig& config, const Seed000Room& room,
                                 int scans, bool median_of_scans, bool round_objects_from_scans) {
  sim::ExperimentConfig room_config = config;
  room_config.world = room.world;
  room_config.world_path = room.world_path;
  Seed000RoomResult result;
  result.room = room;
  try {
    result.rig = TakeBackToBackScans(room_config, room.rig_W,
                                     room.rig_theta_deg * std::numbers::pi / 180.0, scans);
  } catch (const sim::SpawnRefused& e) {
    // At the origin the rig ignores robot.spawn, so the runner's "robot.spawn: ...; choose a free
    // spawn" named a key whose change would not help (s43): name rig_at, which would.
    if (room.rig_at_spawn) throw;
    throw sim::ConfigError(
        config.source_file, "seed000_rooms.rig_at",
        "origin: the rig does not fit at the origin of " + room.world_path.filename().string() +
            ": " + e.problem() +
            "; set seed000_rooms.rig_at: spawn with a robot.spawn where it fits");
  }
  if (median_of_scans) {
    MedianOfScans(&result.rig.front);
    MedianOfScans(&result.rig.back);
  }
  result.scans = MakeTruthScans(result.rig, room.range_cut_m);
  sim::LinesConfig lines = config.lines;
  if (!lines.given) lines.extractors = perception::LineExtractorNames();
  if (round_objects_from_scans) {
    const KnownRoundObjects known = RoundObjectsOfMedianScan(result.rig, room.range_cut_m, lines);
    result.scores = ScoreExtractors(result.scans, lines, &known);
    result.spot_round_objects = known.circles;
  } else {
    result.scores = ScoreExtractors(result.scans, lines);
  }
  return result;
}

}  // namespace plywood::eval
