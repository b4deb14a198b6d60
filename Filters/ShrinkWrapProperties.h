// Shrink Wrap's properties, each beside the core setting it stands for, with its label, unit and
// range: the one list that the defaults, the checks, the core's settings and PrintSelf read.
// Included by vtkShrinkWrapFilter.cxx alone.
#ifndef ShrinkWrap_ShrinkWrapProperties_h
#define ShrinkWrap_ShrinkWrapProperties_h

#include "PropertyBinding.h"
#include "vtkInputGeometry.h"
#include "vtkShrinkWrapFilter.h"

#include "Wrap/WrapSettings.h"

namespace convert = shrinkwrap::convert;

// bind(info, property, setting).
template <typename Filter, typename Settings, typename Bind>
void vtkShrinkWrapFilter::BindProperties(Filter& f, Settings& s, Bind&& bind)
{
  using P = convert::PropertyInfo;
  auto& e = s.evolution;
  // The three sizes most wraps set, and how the wrap meets holes and blocks.
  bind(P{ "TargetEdgeLength", "Target Edge Length", "in the target's units", 0, convert::kNoLimit,
         "automatic" },
    f.TargetEdgeLength, s.targetEdgeLength);
  bind(P{ "GapSize", "Gap Size", "in the target's units", 0, convert::kNoLimit, "automatic" },
    f.GapSize, s.gapSize);
  bind(P{ "NumberOfSteps", "Number Of Steps", "steps", 0, kMaxSteps }, f.NumberOfSteps, s.steps);
  bind(P{ "CloseHoles", "Close Holes", "", 0, 1 }, f.CloseHoles, s.closeHoles);
  bind(P{ "EdgeLengthRange", "Edge Length Range", "in units of the Target Edge Length",
         shrinkwrap::WrapSettings::kShortestEdge, shrinkwrap::WrapSettings::kLongestEdge },
    f.EdgeLengthRange, s.edgeLengthRange);
  bind(P{ "Remeshing", "Remeshing", "", 0, 1 }, f.Remeshing, s.remeshing);
  bind(P{ "Resolution", "Resolution", "cells along the longest side", 8, 1024 }, f.Resolution,
    s.resolution);
  // The start.
  bind(P{ "StartingShape", "Starting Shape", "", ICOSPHERE, OFFSET_SURFACE }, f.StartingShape,
    s.start.shape);
  bind(
    P{ "StartOffsetInCells", "Start Offset In Cells", "in cells of the distance field", 0.5, 1000 },
    f.StartOffsetInCells, s.start.offset);
  bind(P{ "SubdivisionLevel", "Subdivision Level", "", 0, 8 }, f.SubdivisionLevel,
    s.start.subdivision);
  bind(P{ "InitialRelaxation", "Initial Relaxation", "iterations", 0, 1000 }, f.InitialRelaxation,
    s.start.relaxation);
  // Eqs. (3)-(5).
  bind(P{ "TimePerStep", "Time Per Step", "evolution time", 1e-4, 1 }, f.TimePerStep, e.timeStep);
  bind(P{ "AdvectionSpeed", "Advection Speed", "per unit of evolution time", 0, 100 },
    f.AdvectionSpeed, e.C);
  bind(P{ "ConcavityPush", "Concavity Push", "without unit", 0, 10 }, f.ConcavityPush, e.D);
  bind(P{ "Smoothing", "Smoothing", "without unit", 0, 100 }, f.Smoothing, e.C1);
  bind(P{ "SmoothingFalloff", "Smoothing Falloff", "squared scaled units", 0, 100 },
    f.SmoothingFalloff, e.C2);
  bind(
    P{ "AutomaticScaling", "Automatic Scaling", "", 0, 1 }, f.AutomaticScaling, s.automaticScaling);
  bind(P{ "SolverTolerance", "Solver Tolerance", "relative residual", 1e-15, 1e-2 },
    f.SolverTolerance, e.solverTolerance);
  // The tangential redistribution (Section 2.3, eq. (10)).
  bind(P{ "TangentialRedistribution", "Tangential Redistribution", "", NONE, VOLUME },
    f.TangentialRedistribution, e.redistribution);
  bind(P{ "AngleWeight", "Angle Weight", "without unit", 0, 100 }, f.AngleWeight, e.omegaAngle);
  bind(P{ "VolumeWeight", "Volume Weight", "without unit", 0, 100 }, f.VolumeWeight, e.omegaVolume);
  bind(P{ "DistanceWeighting", "Distance Weighting", "", 0, 1 }, f.DistanceWeighting,
    e.distanceWeight);
  bind(P{ "DistanceWeightAmplitude", "Distance Weight Amplitude", "without unit", 0, 100 },
    f.DistanceWeightAmplitude, e.rhoA);
  // The connectivity edits, the rims and the landing.
  bind(P{ "EdgeFlips", "Edge Flips", "", 0, 1 }, f.EdgeFlips, e.edgeFlips);
  bind(P{ "FlipDihedralLimit", "Flip Dihedral Limit", "degrees", 0, 180 }, f.FlipDihedralLimit,
    e.flips.maxDihedral);
  bind(P{ "EdgeCollapses", "Edge Collapses", "", 0, 1 }, f.EdgeCollapses, e.edgeCollapses);
  bind(P{ "CoverRims", "Cover Rims", "", 0, 1 }, f.CoverRims, e.rims.cover);
  bind(P{ "CreaseAngle", "Crease Angle", "degrees", 0, 180 }, f.CreaseAngle, e.rims.creaseAngle);
  bind(P{ "FitFacets", "Fit Facets", "", 0, 1 }, f.FitFacets, e.facetFit);
  bind(P{ "CacheMemoryMiB", "Cache Memory (MiB)", "MiB", 0, 65536 }, f.CacheMemoryMiB, s.cacheMiB);
}

// The properties that stand for no core setting.
namespace
{
const convert::PropertyInfo kInputGeometry{ "InputGeometry", "Input Geometry", "",
  vtkInputGeometry::AUTOMATIC, vtkInputGeometry::POLYGONS_AND_POINTS };
const convert::PropertyInfo kWrapPerBlock{ "WrapPerBlock", "Wrap Per Block", "", 0, 1 };
const convert::PropertyInfo kPassTargetArrays{ "PassTargetArrays", "Pass Target Arrays", "", 0, 1 };
const convert::PropertyInfo kTimeMode{ "TimeMode", "Time Mode", "",
  vtkShrinkWrapFilter::TIME_AUTOMATIC, vtkShrinkWrapFilter::TIME_FOLLOW_TARGET };
}

#endif
