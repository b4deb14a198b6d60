// Every setting of a wrap as the user gives it, with Shrink Wrap's defaults: the one place they are
// stated (the filter's properties start from them). Sizes left unset are chosen by the plan
// (WrapPlan.h), which also gives the evolver and the start the settings they run with.
#ifndef ShrinkWrap_WrapSettings_h
#define ShrinkWrap_WrapSettings_h

#include "Common/Status.h"
#include "Evolution/Evolver.h"
#include "Evolution/StartingSurface.h"

#include <array>
#include <optional>

namespace shrinkwrap
{

struct WrapSettings
{
  EvolverSettings evolution;    // eqs. (2)-(4) and the connectivity edits; its remeshing is planned
  StartSettings start;          // the start's shape, offset (cells) and relaxation
  int steps = 25;               // N_t, evolution steps (the paper's Fig. 11: 200 from an icosphere)
  bool automaticScaling = true; // phi of Section 2.4
  int resolution = 80;          // cells along the longest side of the field computed here
  double cacheMiB = 512;        // memory for cached steps, MiB
  bool remeshing = true;        // remesh after every step towards the Target Edge Length L
  std::optional<double> targetEdgeLength;        // L, target units; unset: automatic
  std::array<double, 2> edgeLengthRange{ 1, 1 }; // adaptive edges between these times L; {1, 1}: L
  std::optional<double>
    gapSize; // narrower gaps are bridged (GapClosing.h), target units; unset: automatic
  bool closeHoles = false;     // an open target's field signed by winding number (WindingSign.h)
  bool exactNearTarget = true; // d and grad d from the target's closest point near it
  double exactBand = 2;        // how near, in cells of the field

  // Automatic sizes of a mesh: the diagonal of the target's box over these.
  static constexpr double kLengthDivisor = 50;
  static constexpr double kGapDivisor = 50;
  static constexpr double kMaxVertices =
    4e6; // a Target Edge Length that would make more is refused
  static constexpr double kChordError = 0.12;  // adaptive edges: the largest chord error, in L
  static constexpr double kShortestEdge = 0.1; // the bounds of edgeLengthRange
  static constexpr double kLongestEdge = 4;

  // Why these settings cannot make a wrap, in the panel's words; empty when they can.
  Status validate() const;
};

} // namespace shrinkwrap

#endif
