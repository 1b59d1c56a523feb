#include "eval/sonar_map/sonar_net_training.h"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <random>
#include <sstream>
#include <stdexcept>
#include <string>
#include <system_error>
#include <vector>

#include "eval/sonar_map/sonar_ground_truth.h"
#include "msgs/angle_units.h"
#include "perception/sonar_map/sonar_cell_model.h"
#include "sim/config/robot_catalog.h"
#include "sim/raycast/mujoco_ray_caster.h"
#include "sim/runner/file_stamp.h"
#include "sim/runner/file_writer.h"
#include "sim/runner/format_number.h"
#include "sim/runner/link_to_nowhere.h"
#include "sim/runner/scratch_folder.h"
#include "sim/runner/text_file.h"
#include "sim/sensors/sonar_sensor.h"
#include "sim/world/occupancy_raster.h"
#include "sim/world/scene.h"

namespace plywood::eval {
namespace {

struct ObstacleBox {
  double cx, cy, hx, hy;
};

struct RandomRoom {
  double half_x = 0, half_y = 0;
  std::vector<ObstacleBox> obstacles;
};

// Rooms 2-5 m by 2-4.5 m with 0-3 boxes (0.25-0.8 m) placed freely or against a wall: the kinds of
// scene seed 001 maps, but never its four evaluation layouts (3.5 x 3.0 m exactly).
RandomRoom MakeRoom(std::mt19937_64& rng) {
  std::uniform_real_distribution<double> u(0.0, 1.0);
  RandomRoom room;
  do {
    room.half_x = 1.0 + 1.5 * u(rng);
    room.half_y = 1.0 + 1.25 * u(rng);
  } while (std::abs(room.half_x - 1.75) < 0.05 && std::abs(room.half_y - 1.5) < 0.05);
  const int n = static_cast<int>(4 * u(rng));
  for (int i = 0; i < n; ++i) {
    ObstacleBox b;
    b.hx = 0.125 + 0.275 * u(rng);
    b.hy = 0.125 + 0.275 * u(rng);
    b.cx = (room.half_x - b.hx) * (2 * u(rng) - 1);
    b.cy = (room.half_y - b.hy) * (2 * u(rng) - 1);
    const double side = u(rng);  // half the boxes touch a wall, as in layouts 2 and 3
    if (side < 0.125)
      b.cx = room.half_x - b.hx;
    else if (side < 0.25)
      b.cx = -room.half_x + b.hx;
    else if (side < 0.375)
      b.cy = room.half_y - b.hy;
    else if (side < 0.5)
      b.cy = -room.half_y + b.hy;
    room.obstacles.push_back(b);
  }
  return room;
}

std::string RoomMjcf(const RandomRoom& room) {
  std::ostringstream s;
  const double t = 0.009, hx = room.half_x, hy = room.half_y;
  s << "<mujoco model=\"train_room\"><worldbody>\n"
    << "<geom name=\"floor\" type=\"plane\" size=\"" << hx + 1 << ' ' << hy + 1 << " 0.05\"/>\n"
    << "<geom type=\"box\" pos=\"0 " << -hy - t << " 0.5\" size=\"" << hx + 2 * t << ' ' << t
    << " 0.5\"/>\n"
    << "<geom type=\"box\" pos=\"0 " << hy + t << " 0.5\" size=\"" << hx + 2 * t << ' ' << t
    << " 0.5\"/>\n"
    << "<geom type=\"box\" pos=\"" << -hx - t << " 0 0.5\" size=\"" << t << ' ' << hy
    << " 0.5\"/>\n"
    << "<geom type=\"box\" pos=\"" << hx + t << " 0 0.5\" size=\"" << t << ' ' << hy
    << " 0.5\"/>\n";
  for (const ObstacleBox& b : room.obstacles)
    s << "<geom type=\"box\" pos=\"" << b.cx << ' ' << b.cy << " 0.3\" size=\"" << b.hx << ' '
      << b.hy << " 0.3\"/>\n";
  s << "</worldbody></mujoco>\n";
  return s.str();
}

struct Dataset {
  std::vector<perception::SonarSample> samples;
  // For the classical model: the ring and the point of each sample.
  std::vector<msgs::RangeRing> rings;
  std::vector<std::pair<int, Eigen::Vector2d>> points;
};

// One room: `poses` random robot poses at least 0.3 m from everything, a ring each, and the 14 x
// 14 local grid's cells (a random point inside each cell, so the net sees every angle) labelled
// from the reachable-space ground truth.
void Generate(const RandomRoom& room, int poses, const sim::SonarOptions& sonar_options,
              const std::filesystem::path& dir, int index, std::mt19937_64& rng, Dataset* out) {
  const std::filesystem::path world = dir / ("room_" + std::to_string(index) + ".xml");
  {
    sim::FileWriter f(world);
    f.out() << RoomMjcf(room);
    f.Close();
  }
  sim::SceneOptions so;
  so.world_mjcf = world;
  so.robot_mjcf = sim::FindRobot("magellan_pro").mjcf;
  so.spawn = {0.0, 0.0, 0.0};
  sim::Scene scene(so);
  sim::OccupancyRasterOptions ro;
  ro.resolution_m = 0.01;
  const sim::OccupancyRaster raster = sim::RasteriseOccupancy(scene.model(), ro);
  sim::SonarSensor sonar(scene, sim::SonarSensor::DefaultSiteNames(), sonar_options, rng());
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int made = 0, tries = 0;
  while (made < poses && tries < 100 * poses) {
    ++tries;
    const double x = (room.half_x - 0.3) * (2 * u(rng) - 1);
    const double y = (room.half_y - 0.3) * (2 * u(rng) - 1);
    const double theta = 2 * kPi * u(rng);
    bool clear = true;
    for (const ObstacleBox& b : room.obstacles)
      if (std::abs(x - b.cx) < b.hx + 0.3 && std::abs(y - b.cy) < b.hy + 0.3) clear = false;
    if (!clear) continue;
    scene.PlaceRobot({x, y, theta});
    sim::MujocoRayCaster caster(scene.model(), scene.data());
    const msgs::RangeRing ring = sonar.Measure(scene, caster);
    const eval::ReachableSpace space = eval::ComputeReachableSpace(raster, {x, y});
    const int ring_index = static_cast<int>(out->rings.size());
    out->rings.push_back(ring);
    const double c = std::cos(theta), s = std::sin(theta);
    for (int j = 0; j < 14; ++j)
      for (int i = 0; i < 14; ++i) {
        const Eigen::Vector2d p_R((i - 7 + u(rng)) * 0.1, (j - 7 + u(rng)) * 0.1);
        const Eigen::Vector2d p_W(x + c * p_R.x() - s * p_R.y(), y + s * p_R.x() + c * p_R.y());
        perception::SonarSample sample;
        sample.x = perception::NormalisedFeatures(perception::ComputeCellFeatures(ring, p_R),
                                                  ring.range_max_m);
        sample.occupied = space.IsFree(p_W) ? 0.0 : 1.0;
        out->samples.push_back(sample);
        out->points.emplace_back(ring_index, p_R);
      }
    ++made;
  }
}

// The working folder of the generated room files, removed however training ends.
class TemporaryFolder {
 public:
  TemporaryFolder() : path_(sim::ScratchFolderRoot() / (kPrefix + std::to_string(::getpid()))) {
    sim::RemoveScratchOfEndedProcesses(path_.parent_path(), kPrefix);  // left by killed trainings
    std::filesystem::create_directories(path_);
  }
  ~TemporaryFolder() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryFolder(const TemporaryFolder&) = delete;
  TemporaryFolder& operator=(const TemporaryFolder&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  static constexpr const char* kPrefix = "plywood-train-";
  std::filesystem::path path_;
};

// Refuses a set whose cells are all one class: a net trained on it learns a constant, and a
// score on it cannot tell the models apart (s51: --test-rooms 1 --poses 1, seed 1, held out 196
// free cells, and the constant base rate scored accuracy 1.0000 beside the net's, exit 0).
void RequireBothClasses(const Dataset& set, const char* flag, int rooms, int poses) {
  double occupied = 0.0;
  for (const auto& s : set.samples) occupied += s.occupied;
  if (occupied > 0.0 && occupied < static_cast<double>(set.samples.size())) return;
  throw std::invalid_argument(
      std::string("train: --") + flag + ": the " + std::to_string(set.samples.size()) +
      " cells of " + std::to_string(rooms) + (rooms == 1 ? " room" : " rooms") + " x " +
      std::to_string(poses) + (poses == 1 ? " pose" : " poses") + " are all " +
      (occupied > 0.0 ? "occupied" : "free") +
      ": one class trains a constant and scores nothing (the constant base rate is always right "
      "on it); give more --" +
      flag + " or --poses");
}

}  // namespace

void SonarNetTrainingOptions::Validate() const {
  auto count = [](const char* name, int value) {
    if (value < 1 || value > 100000)
      throw std::invalid_argument(std::string(name) +
                                  ": must be a whole number in [1, 100000], got " +
                                  std::to_string(value));
  };
  count("rooms", rooms);
  count("test_rooms", test_rooms);
  count("poses", poses);
  // Each ring keeps its 14 x 14 labelled cells in memory (about 20 kB with the classical model's
  // points): --rooms 100000 --poses 100000 (1e10 rings, 200 TB) was accepted and grew until the
  // memory ran out. 100000 rings is about 2 GB; the defaults make 1875.
  const double rings = (static_cast<double>(rooms) + test_rooms) * poses;
  if (rings > static_cast<double>(kMaxSonarRings)) {
    throw std::invalid_argument(
        "poses: (rooms + test_rooms) x poses = " + sim::FormatNumber(rings) +
        " sonar rings, more than the limit of " + std::to_string(kMaxSonarRings) +
        " (each keeps its 196 labelled cells, about 20 kB, in memory)");
  }
  train.Validate();
  sonar.Validate();
  if (out.empty()) throw std::invalid_argument("out: needs a file name");
  // "x.txt/" made the folder x.txt, trained, then failed to write ("Is a directory", exit 1, s57).
  const std::string last = out.filename().string();
  if (last.empty() || last == "." || last == "..") {
    throw std::invalid_argument("out: " + out.string() +
                                " names a folder (it ends in '/', '.' or '..'); give the weights "
                                "file's name");
  }
  std::error_code error;
  if (std::filesystem::is_directory(out, error)) {
    // Found only after training, as exit 1, before fuzz30.
    throw std::invalid_argument("out: " + out.string() +
                                " is a folder; give the weights file's name");
  }
}

std::filesystem::path ShippedSonarNetPath() {
  return sim::DataRoot() / "models" / "sonar_net_v1.txt";
}

std::vector<std::filesystem::path> ShippedSonarNetPaths() {
  return {ShippedSonarNetPath(), sim::DataRoot() / "models" / "sonar_net_edges_v1.txt"};
}

void RefuseShippedSonarNet(const std::filesystem::path& out) {
  namespace fs = std::filesystem;
  // A device or a pipe is no model file; /dev/stdout into a pipe (no path to resolve) was refused
  // "plywood: /dev/stdout: No such file or directory" (s63 fiftieth pass).
  if (sim::IsADeviceOrAPipe(out)) return;
  for (const fs::path& shipped : ShippedSonarNetPaths()) {
    std::error_code error;
    const bool same_file = fs::equivalent(out, shipped, error);  // false if either is missing
    if (same_file || fs::weakly_canonical(out) == fs::weakly_canonical(shipped)) {
      throw std::invalid_argument(
          out.string() + ": is the shipped model (" + shipped.string() +
          "), which training never overwrites; train elsewhere and compare before copying it");
    }
  }
}

void RequireWritablePlace(const std::filesystem::path& out) {
  // A file of the name the weights are staged under (sim::WriteTextFile), made and removed: a
  // read-only file system or a folder plywood may not write in (/sys) was found only when the
  // trained weights were saved, minutes later, as exit 1.
  // A device or a pipe is written to as it is (sim::WriteTextFile), not beside: nothing to probe.
  if (sim::IsADeviceOrAPipe(out)) return;
  const std::string probe = sim::StagedTextFilePath(out).string();
  const int fd = open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    throw std::invalid_argument("train: --out: " + out.string() +
                                ": cannot write there: " + std::strerror(errno));
  }
  close(fd);
  unlink(probe.c_str());
}

SonarNetTrainingReport TrainSonarNet(
    const SonarNetTrainingOptions& options,
    const std::function<void(const SonarNetDataSummary&)>& on_data) {
  options.Validate();
  RefuseShippedSonarNet(options.out);
  const perception::SonarNetTrainOptions& train = options.train;
  SonarNetTrainingReport report;
  report.out = options.out;
  // Before the long part, so an unwritable place fails at once.
  if (options.out.has_parent_path()) {
    // The default --out, runs/sonar_net/, in a folder plywood may not write in (a read-only
    // current folder) read "plywood: runs/sonar_net: Operation not permitted", exit 1.
    if (const auto nowhere = sim::LinkToNowhere(options.out.parent_path())) {
      throw std::invalid_argument("train: --out: " + options.out.string() + ": its folder " +
                                  options.out.parent_path().string() + " " + *nowhere);
    }
    std::error_code error;
    std::filesystem::create_directories(options.out.parent_path(), error);
    if (error) {
      throw std::invalid_argument("train: --out: " + options.out.string() +
                                  ": cannot create its folder " +
                                  options.out.parent_path().string() + ": " + error.message());
    }
  }
  RequireWritablePlace(options.out);
  const sim::FileStamp out_at_start = sim::StampOf(options.out);
  sim::ScratchFolderRoot();  // the rooms' files go there: a bad TMPDIR is named before training

  std::mt19937_64 rng(train.seed);
  Dataset train_set, test_set;
  {
    const TemporaryFolder folder;
    for (int r = 0; r < options.rooms + options.test_rooms; ++r) {
      const RandomRoom room = MakeRoom(rng);
      Generate(room, options.poses, options.sonar, folder.path(), r, rng,
               r < options.rooms ? &train_set : &test_set);
    }
  }
  RequireBothClasses(train_set, "rooms", options.rooms, options.poses);
  RequireBothClasses(test_set, "test-rooms", options.test_rooms, options.poses);
  report.data = {options.rooms, options.test_rooms, train_set.samples.size(),
                 test_set.samples.size()};
  if (on_data) on_data(report.data);

  perception::SonarNet net(train.hidden, train.seed);
  report.train_loss = net.Train(train_set.samples, train);

  std::vector<double> labels, p_net, p_classical, p_prior;
  const perception::ClassicalSonarModel classical;
  double occupied = 0.0;
  for (const auto& s : train_set.samples) occupied += s.occupied;
  const double base_rate = occupied / static_cast<double>(train_set.samples.size());
  for (std::size_t i = 0; i < test_set.samples.size(); ++i) {
    labels.push_back(test_set.samples[i].occupied);
    p_net.push_back(net.Forward(test_set.samples[i].x));
    const auto& [ring, p_R] = test_set.points[i];
    p_classical.push_back(classical.Probability(test_set.rings[ring], p_R));
    p_prior.push_back(base_rate);
  }
  report.net = perception::ScoreProbabilities(p_net, labels);
  report.classical = perception::ScoreProbabilities(p_classical, labels);
  report.base_rate = perception::ScoreProbabilities(p_prior, labels);
  // Staged and renamed into place: a failed write leaves an earlier file as it was.
  net.RequireLoadable(options.out.string());
  // Another process wrote --out while this one trained (two trainings into one file): the rename
  // would replace its weights, and both would exit 0 saying they wrote theirs there. The first to
  // finish wins; the later keeps its weights beside and says so.
  if (!sim::IsADeviceOrAPipe(options.out) && sim::StampOf(options.out) != out_at_start) {
    const std::filesystem::path beside = sim::StagedTextFilePath(options.out);
    sim::WriteTextFile(beside, net.ToText());
    throw std::invalid_argument("train: --out: " + options.out.string() +
                                ": another process wrote it while this one trained; these "
                                "weights are in " +
                                beside.string() + " (choose another --out, or move them there)");
  }
  sim::WriteTextFile(options.out, net.ToText());
  return report;
}

}  // namespace plywood::eval
