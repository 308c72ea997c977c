// VoxelReferenceCaster: the full-resolution reference of DESIGN.md ("Image metrics and
// references"): the paper's standard volume ray casting done carefully on the original voxels.
// Trilinear interpolation, samples every half of the smallest spacing (>= 2 per voxel), each step
// integrated exactly (ExactIntegrator, scalar linear between samples), no early termination, all in
// double precision. Same camera and transfer function as the tet caster, so images compare.
#ifndef art_VoxelReferenceCaster_h
#define art_VoxelReferenceCaster_h

#include "AdaptiveRTTetRayCastModule.h"
#include "Camera.h"
#include "Image.h"
#include "TetRayCaster.h"
#include "TransferFunction.h"

#include <array>
#include <string>
#include <vector>

class vtkImageData;

namespace art
{
class ADAPTIVERTTETRAYCAST_EXPORT VoxelReferenceCaster
{
public:
  /// Point-sampled volume: dims[0] x dims[1] x dims[2] values, x fastest. `first`: the first
  /// voxel's index (i, j, k) in its image's extent, for naming a bad voxel (default 0, 0, 0).
  VoxelReferenceCaster(std::vector<double> values, const int dims[3], const Vec3& origin, const Vec3& spacing,
    TransferFunction tf, const int first[3] = nullptr);
  /// Honours the image's direction matrix (any invertible one: a rotation, a reflection, a shear).
  static VoxelReferenceCaster FromVTK(vtkImageData* image, TransferFunction tf, const std::string& file = {});
  /// The reference for what the tet caster draws with settings s: its transfer function, mode,
  /// iso-surfaces and clipping planes.
  static VoxelReferenceCaster FromVTK(vtkImageData* image, const RenderSettings& s, const std::string& file = {});
  /// Index axes in world coordinates: world = origin + R (i h0, j h1, k h2), R row-major and
  /// invertible (throws art::Error otherwise). Identity by default.
  void SetDirection(const double r[9]);

  /// Samples per smallest voxel spacing (default 2).
  void SetSamplesPerVoxel(double n) { PerVoxel = n < 1 ? 1 : n; }
  /// Maximum-intensity projection instead of emission-absorption.
  void SetMaxIntensity(bool on) { Mip = on; }
  /// Iso-surfaces composited where the trilinear field crosses them between samples, shaded by the
  /// same headlight as the tet caster (ambient + diffuse |n . view|) with the field's own gradient.
  void SetIsoSurfaces(std::vector<IsoSurface> isos, double ambient = 0.3, double diffuse = 0.7)
  {
    Isos = std::move(isos), Ambient = ambient, Diffuse = diffuse;
  }

  /// Clipping planes (a, b, c, d) in world coordinates: only a x + b y + c z + d >= 0 is drawn,
  /// as RenderSettings::clipPlanes for the tet caster.
  void SetClipPlanes(std::vector<std::array<double, 4>> planes) { Planes = std::move(planes); }

  RenderStats Render(const Camera& cam, Image& img, Progress* progress = nullptr) const;
  /// Trilinear value at p, in the volume's own axis-aligned frame (p inside the box).
  double Sample(const Vec3& p) const;
  /// Gradient of the trilinear field at p by central differences over half the smallest spacing.
  Vec3 Gradient(const Vec3& p) const;
  /// The box in the volume's own frame (the world box when the direction is the identity).
  const Box3& Bounds() const { return Box; }

private:
  std::vector<double> V;
  int D[3];
  Vec3 O, H;
  double Inv[9] = { 1, 0, 0, 0, 1, 0, 0, 0, 1 }; ///< the direction's inverse, row-major
  bool Turned = false;                           ///< the direction is not the identity
  Box3 Box;
  TransferFunction TF;
  double PerVoxel = 2;
  bool Mip = false;
  std::vector<IsoSurface> Isos;
  double Ambient = 0.3, Diffuse = 0.7;
  std::vector<std::array<double, 4>> Planes;
};
} // namespace art

#endif
