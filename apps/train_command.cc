#include "apps/train_command.h"

#include <mujoco/mujoco.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>

#include "apps/command_line.h"
#include "eval/sonar_map/sonar_ground_truth.h"
#include "perception/sonar_map/sonar_cell_model.h"
#include "perception/sonar_map/sonar_net.h"
#include "sim/config/robot_catalog.h"
#include "sim/raycast/mujoco_ray_caster.h"
#include "sim/sensors/sonar_sensor.h"
#include "sim/world/occupancy_raster.h"
#include "sim/world/scene.h"

namespace plywood::apps {
namespace {

constexpr double kPi = 3.14159265358979323846;

struct Box {
  double cx, cy, hx, hy;
};

struct RandomRoom {
  double half_x = 0, half_y = 0;
  std::vector<Box> obstacles;
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
    Box b;
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
  for (const Box& b : room.obstacles)
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
void Generate(const RandomRoom& room, int poses, const std::filesystem::path& dir, int index,
              std::mt19937_64& rng, Dataset* out) {
  const std::filesystem::path world = dir / ("room_" + std::to_string(index) + ".xml");
  {
    std::ofstream f(world);
    f << RoomMjcf(room);
  }
  sim::SceneOptions so;
  so.world_mjcf = world;
  so.robot_mjcf = sim::FindRobot("magellan_pro").mjcf;
  so.spawn = {0.0, 0.0, 0.0};
  sim::Scene scene(so);
  sim::OccupancyRasterOptions ro;
  ro.resolution_m = 0.01;
  const sim::OccupancyRaster raster = sim::RasteriseOccupancy(scene.model(), ro);
  sim::SonarOptions sonar_options;  // specular misses on, as in the experiments
  sim::SonarSensor sonar(scene, sim::SonarSensor::DefaultSiteNames(), sonar_options, rng());
  const mjModel* m = scene.model();
  mjData* d = scene.mutable_data();
  const int qpos = m->jnt_qposadr[m->body_jntadr[scene.base_body_id()]];
  std::uniform_real_distribution<double> u(0.0, 1.0);
  int made = 0, tries = 0;
  while (made < poses && tries < 100 * poses) {
    ++tries;
    const double x = (room.half_x - 0.3) * (2 * u(rng) - 1);
    const double y = (room.half_y - 0.3) * (2 * u(rng) - 1);
    const double theta = 2 * kPi * u(rng);
    bool clear = true;
    for (const Box& b : room.obstacles)
      if (std::abs(x - b.cx) < b.hx + 0.3 && std::abs(y - b.cy) < b.hy + 0.3) clear = false;
    if (!clear) continue;
    d->qpos[qpos + 0] = x;
    d->qpos[qpos + 1] = y;
    d->qpos[qpos + 3] = std::cos(theta / 2);
    d->qpos[qpos + 4] = 0.0;
    d->qpos[qpos + 5] = 0.0;
    d->qpos[qpos + 6] = std::sin(theta / 2);
    mj_forward(m, d);
    sim::MujocoRayCaster caster(m, d);
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

std::vector<int> ParseHidden(const std::string& text) {
  std::vector<int> hidden;
  std::stringstream s(text);
  std::string item;
  while (std::getline(s, item, ',')) {
    try {
      hidden.push_back(std::stoi(item));
    } catch (const std::exception&) {
      throw UsageError{"--hidden: expected sizes like 16,16, got '" + text + "'"};
    }
  }
  return hidden;
}

}  // namespace

int TrainCommand(const std::vector<std::string>& args) {
  const CommandLine line(
      args, {"--out", "--rooms", "--test-rooms", "--poses", "--epochs", "--hidden", "--seed"},
      {"--quiet"});
  if (line.positional().size() != 1 || line.positional()[0] != "sonar-net") {
    throw UsageError{
        "usage: plywood train sonar-net [--out FILE] [--rooms N] [--test-rooms N] [--poses N] "
        "[--epochs N] [--hidden H1,H2] [--seed N]"};
  }
  auto count = [&](const std::string& flag, int fallback) {
    const auto v = line.Number(flag);
    if (!v) return fallback;
    if (!(*v >= 1 && *v <= 100000 && *v == std::floor(*v)))
      throw UsageError{flag + ": must be a whole number >= 1"};
    return static_cast<int>(*v);
  };
  const int rooms = count("--rooms", 60);
  const int test_rooms = count("--test-rooms", 15);
  const int poses = count("--poses", 25);
  perception::SonarNetTrainOptions train;
  train.epochs = count("--epochs", 30);
  train.seed = static_cast<std::uint64_t>(count("--seed", 1));
  if (const auto h = line.Value("--hidden")) train.hidden = ParseHidden(*h);
  train.Validate();
  const std::filesystem::path out =
      line.Value("--out").value_or((sim::DataRoot() / "models" / "sonar_net_v1.txt").string());
  const bool quiet = line.Switch("--quiet");

  std::mt19937_64 rng(train.seed);
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("plywood-train-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  Dataset train_set, test_set;
  for (int r = 0; r < rooms + test_rooms; ++r) {
    const RandomRoom room = MakeRoom(rng);
    Generate(room, poses, dir, r, rng, r < rooms ? &train_set : &test_set);
  }
  std::filesystem::remove_all(dir);
  if (!quiet)
    std::printf("data: %d training rooms (%zu cells), %d held-out rooms (%zu cells)\n", rooms,
                train_set.samples.size(), test_rooms, test_set.samples.size());

  perception::SonarNet net(train.hidden, train.seed);
  const double train_loss = net.Train(train_set.samples, train);

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
  const auto s_net = perception::ScoreProbabilities(p_net, labels);
  const auto s_cls = perception::ScoreProbabilities(p_classical, labels);
  const auto s_pri = perception::ScoreProbabilities(p_prior, labels);
  net.Save(out);
  if (!quiet) {
    std::printf("training cross-entropy (last epoch)   %.4f nats\n", train_loss);
    std::printf("%-34s %-14s %s\n", "held-out model", "cross-entropy", "accuracy");
    std::printf("%-34s %-14.4f %.4f\n", "sonar network", s_net.cross_entropy, s_net.accuracy);
    std::printf("%-34s %-14.4f %.4f\n", "classical cone model (Elfes)", s_cls.cross_entropy,
                s_cls.accuracy);
    std::printf("%-34s %-14.4f %.4f\n", "constant base rate", s_pri.cross_entropy, s_pri.accuracy);
    std::printf("weights written to %s\n", out.string().c_str());
  }
  return 0;
}

}  // namespace plywood::apps
