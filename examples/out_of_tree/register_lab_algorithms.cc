#include "register_lab_algorithms.h"

#include <memory>

#include "complementary_odometry.h"
#include "endpoint_fit_extractor.h"

namespace lab {

using plywood::robot::ParameterMap;

void RegisterLabAlgorithms(plywood::perception::AlgorithmRegistry& registry) {
  // Each factory reads its options with the typed getters, which check the range and name the key
  // in their error; plywood reports any key a factory did not read.
  registry.line_extractors.Add({"lab_endpoint_fit", [](const ParameterMap& given) {
                                  EndpointFitOptions o;
                                  o.max_gap_m = given.GetDouble("max_gap_m", o.max_gap_m, 0.0);
                                  o.split_distance_m =
                                      given.GetDouble("split_distance_m", o.split_distance_m, 0.0);
                                  o.min_points = given.GetInt("min_points", o.min_points, 2);
                                  o.min_length_m =
                                      given.GetDouble("min_length_m", o.min_length_m, 0.0);
                                  return std::make_unique<EndpointFitExtractor>(o);
                                }});
  registry.odometry_estimators.Add(
      {"lab_complementary", /*needs_gyro=*/true,
       [](const plywood::robot::OdometryGeometry& geometry,
          const plywood::msgs::Pose2D& X_WR_initial, const ParameterMap& given) {
         ComplementaryOptions o;
         o.gyro_weight = given.GetDouble("gyro_weight", o.gyro_weight, 0.0, 1.0);
         return std::make_unique<ComplementaryOdometry>(geometry, o, X_WR_initial);
       }});
}

}  // namespace lab
