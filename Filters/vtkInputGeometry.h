/**
 * @brief   Which parts of its input Mesh Signed Distance or Shrink Wrap takes (their
 * InputGeometry).
 */
#ifndef vtkInputGeometry_h
#define vtkInputGeometry_h

struct vtkInputGeometry
{
  enum Kind
  {
    AUTOMATIC =
      0, ///< the polygons (and 3-D cells' outer surface) when there are any, else the points
    POLYGONS = 1,           ///< the polygons only; an input without any is an error
    POINTS = 2,             ///< every point of the input, the polygons' corners included
    POLYGONS_AND_POINTS = 3 ///< the polygons, and the points none of them uses
  };
};

#endif
