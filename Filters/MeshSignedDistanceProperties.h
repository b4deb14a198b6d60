// Mesh Signed Distance's properties, each beside the core setting it stands for, with its label,
// unit and range: the one list that the defaults, the checks, the core's settings and PrintSelf
// read. Included by vtkMeshSignedDistance.cxx alone.
#ifndef ShrinkWrap_MeshSignedDistanceProperties_h
#define ShrinkWrap_MeshSignedDistanceProperties_h

#include "PropertyBinding.h"
#include "vtkInputGeometry.h"
#include "vtkMeshSignedDistance.h"

#include "Distance/GridLattice.h"
#include "Distance/SignedDistance.h"

namespace convert = shrinkwrap::convert;

// The core's settings that the properties stand for.
struct vtkMeshSignedDistance::FieldSettings
{
  shrinkwrap::GridPlacement placement;
  shrinkwrap::SignedDistanceSettings distance;
};

// bind(info, property, setting).
template <typename Filter, typename Settings, typename Bind>
void vtkMeshSignedDistance::BindProperties(Filter& f, Settings& s, Bind&& bind)
{
  using P = convert::PropertyInfo;
  bind(P{ "Resolution", "Resolution", "cells along the longest side", 1, 1024 }, f.Resolution,
    s.placement.resolution);
  bind(P{ "CellSize", "Cell Size", "in the input's units", 0, convert::kNoLimit,
         "Resolution sets it" },
    f.CellSize, s.placement.cellSize);
  bind(P{ "BoxScale", "Box Scale", "times the input's bounds", 1, 10 }, f.BoxScale,
    s.placement.boxScale);
  bind(P{ "OffsetFactor", "Offset Factor", "times the largest side", 0, 10 }, f.OffsetFactor,
    s.placement.offsetFactor);
  bind(P{ "SweepMethod", "Sweep Method", "", CLOSEST_POINT, EIKONAL }, f.SweepMethod,
    s.distance.sweep);
  bind(P{ "BandLayers", "Band Layers", "layers of nodes", 0, 16 }, f.BandLayers,
    s.distance.bandLayers);
  bind(P{ "ComputeSign", "Compute Sign", "", 0, 1 }, f.ComputeSign, s.distance.computeSign);
}

namespace
{
// The properties that stand for no core setting.
const convert::PropertyInfo kInputGeometry{ "InputGeometry", "Input Geometry", "",
  vtkInputGeometry::AUTOMATIC, vtkInputGeometry::POLYGONS_AND_POINTS };
const convert::PropertyInfo kUseExplicitGrid{ "UseExplicitGrid", "Use Explicit Grid", "", 0, 1 };
const convert::PropertyInfo kOutputBounds{ "OutputBounds", "Output Bounds", "in the input's units",
  -convert::kNoLimit, convert::kNoLimit };
const convert::PropertyInfo kOutputDimensions{ "OutputDimensions", "Output Dimensions", "nodes", 2,
  convert::kNoLimit };
const convert::PropertyInfo kFieldPerBlock{ "FieldPerBlock", "Field Per Block", "", 0, 1 };
}

#endif
