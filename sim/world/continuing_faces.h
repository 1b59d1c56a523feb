#pragma once

#include "sim/world/ground_truth_walls.h"

namespace plywood::sim {

// Faces of two boxes CONTINUE one another when they face the same way, lie on one line (each one's
// ends within kContinuingFaceOffLineM of the other's line) and touch, overlap or leave a seam of at
// most kContinuingFaceSeamM between them along it. A wall written as two boxes end to end, a long
// wall built from panels, a wall's end face flush with the next wall's outer face at a corner: one
// surface, which a scanner sees as one line. Faces with a gap between them (a doorway) stay apart,
// and so do faces on one line with opposite normals (two boxes back to back across it). Parts of a
// face buried inside another geom are kept, as ExtractGroundTruthWalls keeps them (no beam reaches
// them, so they only lengthen the surface an extracted line may lie along).
//
// Both tolerances are for worlds written by hand to the millimetre, as users write them (s45): a
// wall of three panels of 1.0787 m written `size="0.539"` left 1 mm seams and was scored as three
// walls, each a third of the line the scanner saw (recall 0.5, precision 0.75 in seed000_room_1);
// the same room turned 30 deg, each wall's `pos` rounded to the millimetre, put its south wall's
// two panels 0.16 mm off each other's line (walls_visible 5, recall 0.8).
// - Off the line: rounding a position to 1 mm moves a panel up to 0.71 mm off its line in a turned
//   room, two panels up to 1.41 mm apart; 2 mm holds that, and is a fifth of the LMS 200's 10 mm
//   range noise and a 25th of the scorers' 5 cm endpoint gate, so no scan can tell such faces from
//   one line. (Generated worlds are written with 6 decimals: faces meant to continue land within
//   1.15 um of each other's line, over the 300 worlds of generator seeds 13, 61 and 71.)
// - Along the line: rounding positions and sizes to 1 mm leaves seams of up to 2 mm. A 5 mm seam
//   passes at most one 0.5 deg beam of a scanner 0.6 m or more away (8.7 mrad apart: 5.2 mm there),
//   below the scorers' min_observed_rays of 5, so no extractor can break a line at it; the
//   narrowest gap meant to part two faces is a doorway's 0.3 m, sixty times wider.
inline constexpr double kContinuingFaceOffLineM = 2e-3;
inline constexpr double kContinuingFaceSeamM = 5e-3;

// Two faces' lengths that differ by less than this are equal (rounding in a world file's numbers):
// the lower row then names their surface. Axis-aligned hand-written boxes are exact to 1e-15 m,
// generated ones to 1 um.
inline constexpr double kContinuingFaceToleranceM = 1e-5;

// Fills walls->surfaces and walls->surface_of_segment from walls->segments: each surface is a
// maximal set of faces linked by "continues", on its longest face's line and named by it, its ends
// the outermost ends of its faces projected onto that line (a surface of one face is that face,
// exactly).
void JoinContinuingFaces(GroundTruthWalls* walls);

}  // namespace plywood::sim
