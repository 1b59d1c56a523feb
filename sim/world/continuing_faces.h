#pragma once

#include "sim/world/ground_truth_walls.h"

namespace plywood::sim {

// Faces of two boxes CONTINUE one another when they face the same way, lie on one line (each one's
// ends within kContinuingFaceToleranceM of the other's line) and touch or overlap along it (a gap
// of at most that tolerance). A wall written as two boxes end to end, a long wall built from
// panels, a wall's end face flush with the next wall's outer face at a corner: one surface, which
// a scanner sees as one line. Faces with a gap between them (a doorway) stay apart, and so do
// faces on one line with opposite normals (two boxes back to back across it). Parts of a face
// buried inside another geom are kept, as ExtractGroundTruthWalls keeps them (no beam reaches
// them, so they only lengthen the surface an extracted line may lie along).
//
// The tolerance: generated worlds are written with 6 decimals (1 um positions and sizes, 1e-6 deg
// yaws), so in a turned room two boxes meant to continue one another land up to 1.15 um off each
// other's line and 0.24 um apart along it (measured over the 300 worlds of generator seeds 13, 61
// and 71); the nearest faces that are not meant to continue are 100 um and more off the line, or
// 0.3 m (a doorway) apart. 10 um sits a decade from both, and a thousand times below any
// scanner's range noise; axis-aligned hand-written boxes are exact to 1e-15 m.
inline constexpr double kContinuingFaceToleranceM = 1e-5;

// Fills walls->surfaces and walls->surface_of_segment from walls->segments: each surface is a
// maximal set of faces linked by "continues", on its longest face's line and named by it, its ends
// the outermost ends of its faces projected onto that line (a surface of one face is that face,
// exactly).
void JoinContinuingFaces(GroundTruthWalls* walls);

}  // namespace plywood::sim
