/**
 * @class vtkTetRayCastMapper
 * @brief Cell-by-cell ray casting of a tetrahedral grid into a vtkRenderWindow.
 *
 * A vtkUnstructuredGridVolumeMapper around the AdaptiveRT engine (art::TetRayCaster; Grosso,
 * Luerig & Ertl 1997): rays walk face to face through the tets (Pluecker-consistent exits), each
 * segment is integrated exactly against the vtkVolumeProperty's colour and scalar-opacity
 * functions (ScalarOpacityUnitDistance honoured), iso-surfaces are shaded from interpolated
 * vertex gradients, the volume itself (ShadeOn) from each tet's gradient by a headlight with the
 * property's ambient, diffuse, specular and specular power, and rays stop at the early-termination opacity. The image is computed on all
 * cores at the renderer's size divided by ImageSampleDistance and drawn as a textured quad, like
 * VTK's own ray cast mappers. Non-tetrahedral cells are tetrahedralised first. The volume's
 * matrix is honoured: position, orientation and a uniform scale by casting in the data's
 * coordinates (lengths in data units), a mirror (negative scale) by moving the mesh through it
 * (lengths still in data units), any other matrix (SetScale(1, 1, 3) for thick slices, a shear)
 * by moving the mesh through its linear part (lengths in world units); such meshes are rebuilt
 * when that part changes, not when the volume only moves. Opaque geometry in the scene ends the
 * rays at its depth (IntermixIntersectingGeometry). The mapper's ScalarMode and SelectScalarArray
 * choose the field (cell values are averaged to the points), and VectorMode / VectorComponent what
 * of a vector array (velocity, RGB) is drawn, as vtkSmartVolumeMapper has them; ghost cells (DUPLICATECELL in
 * vtkGhostType) are skipped, as VTK's mappers skip them. Clipping planes (AddClippingPlane,
 * world coordinates, the side the normal points to kept) cut each ray's interval, exact for the
 * linear field; a moving plane only cuts the rays, the mesh is kept. A grey colour function (SetColor with a
 * vtkPiecewiseFunction) is drawn as grey. As VTK's own volume mappers, each frame fires
 * VolumeMapperRenderStartEvent, VolumeMapperRenderProgressEvent (call data: a double in [0, 1],
 * on the thread that called Render) and VolumeMapperRenderEndEvent; when the render window's
 * abort check says so (an interactor's pending event), the frame stops and is not drawn. A label
 * mesh (a cell array "label", as vtkAdaptiveTetReducer's SetLabels writes it) is drawn label by
 * label (LabelColoring): the values inside each label in its own hue by default.
 */
#ifndef vtkTetRayCastMapper_h
#define vtkTetRayCastMapper_h

#include "AdaptiveRTTetRayCastModule.h"
#include "vtkUnstructuredGridVolumeMapper.h"

#include <string> // FrameError

class vtkCamera;
class vtkImageData;
class vtkRayCastImageDisplayHelper;
class vtkUnstructuredGrid;
class vtkVolumeProperty;

class ADAPTIVERTTETRAYCAST_EXPORT vtkTetRayCastMapper : public vtkUnstructuredGridVolumeMapper
{
public:
  static vtkTetRayCastMapper* New();
  vtkTypeMacro(vtkTetRayCastMapper, vtkUnstructuredGridVolumeMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Pixels per ray in each direction (1 = one ray per pixel; 2 = a quarter of the rays). */
  vtkSetClampMacro(ImageSampleDistance, float, 0.1f, 32.0f);
  vtkGetMacro(ImageSampleDistance, float);
  ///@}

  ///@{
  /**
   * With AutoAdjustSampleDistances on (the default, as in VTK's own ray cast mappers), each frame
   * sets ImageSampleDistance, between the minimum (default 1) and the maximum (default 4), from
   * the last frame's time and the time the renderer allocates to this volume (its window's
   * desired update rate): coarse while an interactor moves the camera, one ray a pixel when still.
   * Turn it off to set ImageSampleDistance yourself.
   */
  vtkSetClampMacro(AutoAdjustSampleDistances, vtkTypeBool, 0, 1);
  vtkGetMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkBooleanMacro(AutoAdjustSampleDistances, vtkTypeBool);
  vtkSetClampMacro(MinimumImageSampleDistance, float, 0.1f, 32.0f);
  vtkGetMacro(MinimumImageSampleDistance, float);
  vtkSetClampMacro(MaximumImageSampleDistance, float, 0.1f, 32.0f);
  vtkGetMacro(MaximumImageSampleDistance, float);
  ///@}

  ///@{
  /** Early ray termination: a ray stops once its opacity reaches this (default 0.99; 1 = off). */
  vtkSetClampMacro(EarlyRayTermination, double, 0.01, 1.0);
  vtkGetMacro(EarlyRayTermination, double);
  ///@}

  ///@{
  /** Use the seed paper's trapezoid rule instead of the exact segment integral (default off). */
  vtkSetMacro(TrapezoidRule, vtkTypeBool);
  vtkGetMacro(TrapezoidRule, vtkTypeBool);
  vtkBooleanMacro(TrapezoidRule, vtkTypeBool);
  ///@}

  ///@{
  /**
   * Opaque geometry rendered before the volume (surfaces, slices, outlines) hides what lies behind
   * it: each ray ends at the depth buffer's value for its pixel (default on, as in VTK's
   * vtkUnstructuredGridVolumeRayCastMapper).
   */
  vtkSetClampMacro(IntermixIntersectingGeometry, vtkTypeBool, 0, 1);
  vtkGetMacro(IntermixIntersectingGeometry, vtkTypeBool);
  vtkBooleanMacro(IntermixIntersectingGeometry, vtkTypeBool);
  ///@}

  /** Adds a shaded iso-surface at `value` with colour (r, g, b) and constant opacity. */
  void AddIsoSurface(double value, double r, double g, double b, double opacity);
  void RemoveAllIsoSurfaces();
  int GetNumberOfIsoSurfaces();

  /** Float RGBA (premultiplied, row 0 at the bottom) of the last render, before drawing. */
  vtkImageData* GetLastImage();
  /** Seconds the last image took to compute (without drawing). */
  vtkGetMacro(LastRenderTime, double);
  /** Tets crossed by all rays of the last image. */
  vtkGetMacro(LastTetsCrossed, double);

  enum VectorModeType
  {
    DISABLED = -1, ///< a vector array is an error
    MAGNITUDE = 0, ///< draw each tuple's Euclidean norm
    COMPONENT = 1  ///< draw component VectorComponent
  };
  ///@{
  /**
   * What to draw of a scalar array of several components (vtkSmartVolumeMapper's VectorMode and
   * VectorComponent): MAGNITUDE, COMPONENT VectorComponent (0-based), or DISABLED (the default:
   * such an array is an error naming these settings).
   */
  vtkSetClampMacro(VectorMode, int, DISABLED, COMPONENT);
  vtkGetMacro(VectorMode, int);
  vtkSetClampMacro(VectorComponent, int, 0, 3);
  vtkGetMacro(VectorComponent, int);
  ///@}

  enum LabelColoringType
  {
    LABEL_COLORING_OFF = 0,   ///< labels ignored: the selected scalars through the property's functions
    LABEL_COLORING_FLAT = 1,  ///< each label's tets in the label's colour
    LABEL_COLORING_VALUES = 2 ///< the selected point values inside each label, in its hue
  };
  ///@{
  /**
   * How a grid with a one-component cell array LabelArrayName (default "label") is drawn: split
   * per label, so no two labels blend at their interface. LABEL_COLORING_VALUES (the default):
   * each label's tets by its own functions of the selected point values: the property's
   * SetLabelColor and SetLabelScalarOpacity (VTK's label-map functions) for a label that has
   * them, else the property's colour and scalar-opacity functions in the label's categorical hue
   * (each colour's luminance times the label's colour in Tableau's ten, as ParaView's categorical
   * presets start). When the labels themselves are the selected scalars, or under
   * LABEL_COLORING_FLAT, each label in one colour: the property's label colour at the label, else
   * its categorical colour, half opaque per unit distance unless a label opacity says otherwise.
   * LABEL_COLORING_OFF, maximum intensity and iso-surfaces draw the selected scalars as for any grid.
   */
  vtkSetClampMacro(LabelColoring, int, LABEL_COLORING_OFF, LABEL_COLORING_VALUES);
  vtkGetMacro(LabelColoring, int);
  void SetLabelColoringToOff() { this->SetLabelColoring(LABEL_COLORING_OFF); }
  void SetLabelColoringToFlat() { this->SetLabelColoring(LABEL_COLORING_FLAT); }
  void SetLabelColoringToValues() { this->SetLabelColoring(LABEL_COLORING_VALUES); }
  vtkSetStringMacro(LabelArrayName);
  vtkGetStringMacro(LabelArrayName);
  ///@}

  void Render(vtkRenderer* ren, vtkVolume* vol) override;
  void ReleaseGraphicsResources(vtkWindow*) override;

protected:
  vtkTetRayCastMapper();
  ~vtkTetRayCastMapper() override;

  float ImageSampleDistance = 1.0f;
  vtkTypeBool AutoAdjustSampleDistances = 1;
  float MinimumImageSampleDistance = 1.0f;
  float MaximumImageSampleDistance = 4.0f;
  double LastFrameSeconds = 0.0; ///< the whole last Render call, for AutoAdjustSampleDistances
  double EarlyRayTermination = 0.99;
  vtkTypeBool TrapezoidRule = 0;
  vtkTypeBool IntermixIntersectingGeometry = 1;
  double LastRenderTime = 0.0;
  double LastTetsCrossed = 0.0;
  int VectorMode = DISABLED;
  int VectorComponent = 0;
  int LabelColoring = LABEL_COLORING_VALUES;
  char* LabelArrayName = nullptr;
  int Warned = 0; ///< unsupported settings already named: 2 gradient opacity,
                 ///< 4 IndependentComponents off, 8 the camera's

  /**
   * Warns, once each, of property settings the mapper does not follow for `grid`'s scalars
   * (gradient opacity, IndependentComponents off on a multi-component array).
   */
  void WarnUnsupported(vtkVolumeProperty* p, vtkUnstructuredGrid* grid);
  /**
   * Warns, once, of camera settings the rays do not follow (off-axis projection, user and model
   * transforms, view shear or stereo under parallel projection): opaque geometry moves with them,
   * the volume does not. Window centre, view shear and stereo eyes in perspective are followed.
   */
  void WarnUnsupported(vtkCamera* cam);
  /**
   * An error that stops this frame, said once while it repeats frame after frame (ParaView
   * renders on every interaction); a frame drawn in between lets it be said again.
   */
  void FrameError(const std::string& message);

  ///@{
  /**
   * Render's steps: the input's selected scalars; the matrices between data, engine and world;
   * the engine's mesh (rebuilt when its input changed; false when there is none to draw); the
   * frame's settings from the property; the sample distance for the allotted time; the rays
   * cast (false when the frame was aborted); the image drawn as a textured quad.
   */
  struct Frame;
  bool SelectScalars(Frame& f);
  void PlaceInData(vtkVolume* vol, Frame& f);
  bool UpdateMesh(Frame& f);
  bool FrameSettings(vtkVolume* vol, Frame& f);
  void AdjustSampleDistance(vtkVolume* vol);
  bool CastFrame(vtkRenderer* ren, Frame& f);
  void DrawFrame(vtkRenderer* ren, vtkVolume* vol, Frame& f);
  ///@}

private:
  vtkTetRayCastMapper(const vtkTetRayCastMapper&) = delete;
  void operator=(const vtkTetRayCastMapper&) = delete;

  struct Internals;
  Internals* Impl;
};

#endif
