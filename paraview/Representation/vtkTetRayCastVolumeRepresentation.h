/**
 * @class vtkTetRayCastVolumeRepresentation
 * @brief ParaView's unstructured-grid volume representation drawing through vtkTetRayCastMapper.
 *
 * ParaView's vtkUnstructuredGridVolumeRepresentation registers a fixed list of mappers from its
 * XML sub-proxies; this subclass adds the AdaptiveRT tet ray caster (cell-by-cell walk, exact
 * segment integral; Grosso, Luerig & Ertl 1997) under the name "Tet Ray Cast" and makes it the
 * active one, as ParaView's Surface LIC adds its own mapper. The "Tet Ray Cast Volume"
 * representation type of the plugin's XML is this class. The caster's settings are forwarded:
 * early ray termination, the segment rule, image sample distances, label colouring and
 * iso-surfaces (coloured as `adaptivert render --iso` colours them, in turn from a palette of four).
 *
 * In parallel each rank casts the cells it holds, rays entering and leaving through its piece's
 * boundary faces, and ParaView composites the ranks' images in visibility order. The pieces of a
 * parallel vtkAdaptiveTetReducer (their field "pieces" is the number of ranks on every rank) are
 * boxes of VTK's block split meeting face to face, so they are composited as they are
 * (UseDataPartitions); other data ParaView redistributes first, each cell to one rank, and
 * cells that cross a rank's region are composited with it, not exactly in order.
 */
#ifndef vtkTetRayCastVolumeRepresentation_h
#define vtkTetRayCastVolumeRepresentation_h

#include "AdaptiveRTTetRayCastRepresentationModule.h"
#include "vtkUnstructuredGridVolumeRepresentation.h"

#include <vector> // IsoValues

class vtkTetRayCastMapper;

class ADAPTIVERTTETRAYCASTREPRESENTATION_EXPORT vtkTetRayCastVolumeRepresentation
  : public vtkUnstructuredGridVolumeRepresentation
{
public:
  static vtkTetRayCastVolumeRepresentation* New();
  vtkTypeMacro(vtkTetRayCastVolumeRepresentation, vtkUnstructuredGridVolumeRepresentation);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Forwarded to vtkTetRayCastMapper (see there). */
  void SetEarlyRayTermination(double opacity);
  double GetEarlyRayTermination();
  void SetImageSampleDistance(double pixels);
  void SetAutoAdjustSampleDistances(int on);
  void SetMinimumImageSampleDistance(double pixels);
  void SetMaximumImageSampleDistance(double pixels);
  void SetIntermixIntersectingGeometry(int on);
  ///@}

  enum Integrators
  {
    EXACT = 0,    ///< the exact integral of the linear field's emission and absorption
    TRAPEZOID = 1 ///< the seed paper's trapezoid rule
  };
  /** The segment rule: EXACT (default) or TRAPEZOID. */
  void SetIntegrator(int rule);
  int GetIntegrator();

  ///@{
  /**
   * How a label mesh (a cell array "label") is coloured: vtkTetRayCastMapper's LabelColoring,
   * LABEL_COLORING_VALUES (default: the coloured array's values inside each label, the colour
   * map in each label's hue), LABEL_COLORING_FLAT (each label in one colour) or
   * LABEL_COLORING_OFF (the colour map alone, labels ignored).
   */
  void SetLabelColoring(int mode);
  int GetLabelColoring();
  ///@}

  ///@{
  /** Shaded iso-surfaces drawn with the volume, all at IsoOpacity (default 1). */
  void AddIsoValue(double value);
  void RemoveAllIsoValues();
  void SetIsoOpacity(double opacity);
  ///@}

  /** The caster, for what the forwarded settings do not reach. */
  vtkTetRayCastMapper* GetTetRayCastMapper();

protected:
  vtkTetRayCastVolumeRepresentation();
  ~vtkTetRayCastVolumeRepresentation() override;

  /** Also passes the colour function's vector mode to the caster and its iso-surfaces. */
  void UpdateMapperParameters() override;

  /** Finds whether the input is a parallel reduction's pieces (collective over the ranks). */
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** Asks the view to composite such pieces as they lie, without redistributing them. */
  int ProcessViewRequest(vtkInformationRequestKey* request, vtkInformation* inInfo, vtkInformation* outInfo) override;

private:
  vtkTetRayCastVolumeRepresentation(const vtkTetRayCastVolumeRepresentation&) = delete;
  void operator=(const vtkTetRayCastVolumeRepresentation&) = delete;

  vtkTetRayCastMapper* Mapper;
  std::vector<double> IsoValues;
  double IsoOpacity = 1.0;
  bool IsoChanged = false;
  bool ReducerPieces = false;
};

#endif
