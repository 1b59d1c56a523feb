#pragma once

#include <mujoco/mujoco.h>

#include <cstdint>
#include <vector>

namespace plywood::sim {

// Makes the robot's contacts cost the same in any size of world. MuJoCo 2.2.2 pairs every robot
// geom with every geom of the world body on every step (its broad phase works per body, and putting
// each wall in a body of its own is worse: its sweep-and-prune then enumerates the walls against
// each other, 2.7x the office's physics; zeroing the robot's contype does not stop the enumeration
// either). Instead, while MuJoCo runs, its dynamic search is off (opt.collision = mjCOL_PAIR) and
// the robot gets explicit <pair>s with just the world geoms near it: a uniform 2-D grid of the
// static geoms' footprints, queried with the robot's bounding circle before each mj_step /
// mj_forward. A world with moving bodies keeps MuJoCo's own search. Pair parameters are what
// MuJoCo's dynamic rule would give (priority, else max condim and friction and solmix-weighted
// solref/solimp; larger margin and gap), and the pairs go in the order the dynamic search visits
// them (robot body, world geom, robot geom), so contacts come out the same, to the bit, as without
// this.
//
// The model is compiled with `kCapacity` placeholder pairs (ComposeSceneMjcf adds them); between
// calls m->npair stays at that capacity and the placeholders are inert (robot geoms far apart), so
// mj_copyModel and any outside mj_forward see a consistent model. A step that would need more
// pairs than the capacity falls back to MuJoCo's own search for that step.
class NearContactPairs {
 public:
  static constexpr int kCapacity = 96;

  // @pre `model` holds kCapacity placeholder pairs; `data` has had mj_kinematics (geom poses).
  NearContactPairs(mjModel* model, const mjData* data, int robot_base_body);

  NearContactPairs(const NearContactPairs&) = delete;
  NearContactPairs& operator=(const NearContactPairs&) = delete;

  // Sets the robot's pairs for the robot at the pose in data->qpos; undone by the destructor.
  class Active {
   public:
    ~Active();
    Active(const Active&) = delete;
    Active& operator=(const Active&) = delete;

   private:
    friend class NearContactPairs;
    explicit Active(NearContactPairs* owner) : owner_(owner) {}
    NearContactPairs* owner_;
  };
  [[nodiscard]] Active Activate(const mjData* data);

  // Pairs set by the last Activate (for tests); -1 when it fell back to MuJoCo's search.
  int last_pair_count() const { return last_pair_count_; }

 private:
  struct PairParameters {
    int world_geom, robot_geom, robot_body;
    int dim;
    mjtNum friction[5], solref[mjNREF], solimp[mjNIMP], margin, gap;
  };
  // A static geom's footprint on the floor, grown by its margin.
  struct Footprint {
    double cx = 0.0, cy = 0.0;
    bool rectangle = false;
    double ux = 1.0, uy = 0.0, half_x = 0.0, half_y = 0.0;  // rectangle: x axis and half sizes
    double radius = 0.0;                                    // else: a disc
  };
  // True when a disc of radius reach_m about (x, y) meets the footprint.
  static bool Within(const Footprint& f, double x, double y, double reach_m);
  void Restore();
  void WritePair(int slot, const PairParameters& p);

  mjModel* model_;
  int base_qpos_ = -1;
  double reach_m_ = 0.0;          // robot bounding circle about the base origin, margins included
  std::vector<int> robot_geoms_;  // collidable, by id
  // Candidate pairs of each world geom (in dynamic-search order within the geom), and the world
  // geoms always paired (no bounding radius: planes, height fields; or on moving bodies).
  std::vector<std::vector<PairParameters>> pairs_of_world_geom_;
  std::vector<int> always_;
  // Uniform grid over the static geoms' bounding squares: cell -> world geoms (CSR).
  double x0_ = 0.0, y0_ = 0.0, cell_m_ = 1.0;
  int nx_ = 0, ny_ = 0;
  std::vector<std::uint32_t> cell_begin_, cell_items_;
  std::vector<double> geom_box_;  // footprint bounds per world geom: x_lo, y_lo, x_hi, y_hi
  std::vector<Footprint> footprints_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t stamp_now_ = 0;
  // Scratch and the placeholder pair restored into used slots.
  std::vector<int> near_;
  std::vector<const PairParameters*> active_;
  PairParameters placeholder_{};
  int used_slots_ = 0;
  bool fell_back_ = false;
  bool moving_world_geoms_ = false;
  int saved_collision_ = mjCOL_ALL;
  int last_pair_count_ = 0;
};

}  // namespace plywood::sim
