#include "HessianMetric.h"

#include "Error.h"
#include "ParallelTiles.h"
#include "SymmetricEigen3.h"

#include <algorithm>
#include <cmath>

namespace art
{
namespace
{
std::vector<double> GaussianKernel(double sigma)
{
  const int r = std::max(1, static_cast<int>(std::ceil(3.0 * sigma)));
  std::vector<double> k(2 * static_cast<size_t>(r) + 1);
  double sum = 0;
  for (int i = -r; i <= r; ++i)
  {
    k[i + r] = std::exp(-0.5 * i * i / (sigma * sigma));
    sum += k[i + r];
  }
  for (double& w : k)
  {
    w /= sum;
  }
  return k;
}

long long Index(const int d[3], int i, int j, int k)
{
  return i + static_cast<long long>(d[0]) * (j + static_cast<long long>(d[1]) * k);
}
} // namespace

void HessianMetric::Smooth(std::vector<float>& field, int components, double sigma) const
{
  if (!(sigma > 0))
  {
    return;
  }
  const std::vector<double> kernel = GaussianKernel(sigma);
  const int r = static_cast<int>(kernel.size() / 2);
  for (int axis = 0; axis < 3; ++axis)
  {
    const int n = Dims[axis];
    if (n < 2)
    {
      continue;
    }
    const int a1 = (axis + 1) % 3, a2 = (axis + 2) % 3;
    const long long lines = static_cast<long long>(Dims[a1]) * Dims[a2];
    ForEachRange(lines, 64, [&](long long l0, long long l1, Counters&) {
      std::vector<double> line(static_cast<size_t>(n) * components);
      for (long long l = l0; l < l1; ++l)
      {
        int c[3];
        c[a1] = static_cast<int>(l % Dims[a1]);
        c[a2] = static_cast<int>(l / Dims[a1]);
        auto at = [&](int i) {
          c[axis] = i;
          return static_cast<size_t>(Index(Dims, c[0], c[1], c[2])) * components;
        };
        for (int i = 0; i < n; ++i)
        {
          const size_t p = at(i);
          for (int q = 0; q < components; ++q)
          {
            line[static_cast<size_t>(i) * components + q] = field[p + q];
          }
        }
        for (int i = 0; i < n; ++i)
        {
          const size_t p = at(i);
          for (int q = 0; q < components; ++q)
          {
            double s = 0;
            for (int t = -r; t <= r; ++t)
            {
              const int j = std::min(n - 1, std::max(0, i + t)); // the edge voxel repeats
              s += kernel[t + r] * line[static_cast<size_t>(j) * components + q];
            }
            field[p + q] = static_cast<float>(s);
          }
        }
      }
    });
  }
}

HessianMetric::HessianMetric(const VoxelVolume& volume, const MetricOptions& options, const std::vector<float>* weight,
  const std::function<void(double)>& done)
  : Opt(options)
{
  for (int d = 0; d < 3; ++d)
  {
    Dims[d] = volume.Dims[d];
  }
  const long long n = volume.NumberOfVoxels();
  if (weight && static_cast<long long>(weight->size()) != n)
  {
    throw Error("internal: a metric weight per voxel is needed");
  }
  LambdaFloor = std::max(1e-300, Opt.Floor * std::max(volume.Range[1] - volume.Range[0], 1e-30));
  std::vector<float> s(static_cast<size_t>(n));
  for (long long i = 0; i < n; ++i)
  {
    s[i] = static_cast<float>(volume.Value(i));
  }
  Smooth(s, 1, Opt.Sigma);
  if (done)
  {
    done(0.2);
  }
  // |H| by central differences of the smoothed voxels; at a face the next voxel in holds it.
  H.assign(6 * static_cast<size_t>(n), 0.f);
  ForEachRange(static_cast<long long>(Dims[1]) * Dims[2], 16, [&](long long r0, long long r1, Counters&) {
    for (long long row = r0; row < r1; ++row)
    {
      const int j = static_cast<int>(row % Dims[1]), k = static_cast<int>(row / Dims[1]);
      for (int i = 0; i < Dims[0]; ++i)
      {
        int c[3] = { i, j, k };
        bool flat[3];
        for (int d = 0; d < 3; ++d)
        {
          flat[d] = Dims[d] < 3;
          c[d] = flat[d] ? 0 : std::min(Dims[d] - 2, std::max(1, c[d]));
        }
        auto f = [&](int di, int dj, int dk) { return double(s[Index(Dims, c[0] + di, c[1] + dj, c[2] + dk)]); };
        const double f0 = f(0, 0, 0);
        double h[6] = { 0, 0, 0, 0, 0, 0 };
        const int e[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
        static const int diagonal[3] = { 0, 3, 5 };
        for (int a = 0; a < 3; ++a)
        {
          if (!flat[a])
          {
            h[diagonal[a]] = f(e[a][0], e[a][1], e[a][2]) - 2 * f0 + f(-e[a][0], -e[a][1], -e[a][2]);
          }
        }
        static const int mixed[3][3] = { { 0, 1, 1 }, { 0, 2, 2 }, { 1, 2, 4 } }; // axes a, b and slot
        for (const auto& m : mixed)
        {
          const int a = m[0], b = m[1];
          if (flat[a] || flat[b])
          {
            continue;
          }
          auto g = [&](int sa, int sb) {
            return f(sa * e[a][0] + sb * e[b][0], sa * e[a][1] + sb * e[b][1], sa * e[a][2] + sb * e[b][2]);
          };
          h[m[2]] = 0.25 * (g(1, 1) - g(1, -1) - g(-1, 1) + g(-1, -1));
        }
        const SymmetricEigen3 eig(h);
        const long long idx = Index(Dims, i, j, k);
        const double w = weight ? (*weight)[idx] : 1.0;
        const double l[3] = { w * std::fabs(eig.Values[0]), w * std::fabs(eig.Values[1]), w * std::fabs(eig.Values[2]) };
        double out[6];
        eig.Compose(l, out);
        for (int q = 0; q < 6; ++q)
        {
          H[6 * static_cast<size_t>(idx) + q] = static_cast<float>(out[q]);
        }
      }
    }
  });
  if (done)
  {
    done(0.6);
  }
  Smooth(H, 6, Opt.TensorSigma);
  if (done)
  {
    done(1.0);
  }
}

void HessianMetric::HessianAt(const double p[3], double h[6]) const
{
  int i0[3];
  double f[3];
  for (int d = 0; d < 3; ++d)
  {
    const double c = std::min<double>(Dims[d] - 1, std::max(0.0, p[d]));
    i0[d] = std::min(std::max(0, Dims[d] - 2), static_cast<int>(std::floor(c)));
    f[d] = Dims[d] > 1 ? c - i0[d] : 0.0;
  }
  std::fill(h, h + 6, 0.0);
  for (int corner = 0; corner < 8; ++corner)
  {
    const int o[3] = { corner & 1, (corner >> 1) & 1, (corner >> 2) & 1 };
    double w = 1;
    int c[3];
    for (int d = 0; d < 3; ++d)
    {
      w *= o[d] ? f[d] : 1 - f[d];
      c[d] = std::min(Dims[d] - 1, i0[d] + o[d]);
    }
    if (w == 0)
    {
      continue;
    }
    const float* v = &H[6 * static_cast<size_t>(Index(Dims, c[0], c[1], c[2]))];
    for (int q = 0; q < 6; ++q)
    {
      h[q] += w * v[q];
    }
  }
}

HessianMetric::Local HessianMetric::Decompose(const double p[3]) const
{
  double h[6];
  HessianAt(p, h);
  const SymmetricEigen3 eig(h);
  Local l;
  for (int k = 0; k < 3; ++k)
  {
    l.Lambda[k] = std::max(std::fabs(eig.Values[k]), LambdaFloor);
    for (int d = 0; d < 3; ++d)
    {
      l.Vectors[k][d] = eig.Vectors[k][d];
    }
  }
  return l;
}

namespace
{
// The clamped eigenvalues of the metric at scale D.
void Scaled(const HessianMetric::Local& l, double scale, const MetricOptions& o, double mu[3])
{
  const double s = scale * std::pow(l.Lambda[0] * l.Lambda[1] * l.Lambda[2], -1.0 / (2.0 * o.Exponent + 3.0));
  const double lo = 1.0 / (o.Hmax * o.Hmax), hi = 1.0 / (o.Hmin * o.Hmin);
  for (int k = 0; k < 3; ++k)
  {
    mu[k] = std::min(hi, std::max(lo, s * l.Lambda[k]));
  }
}
} // namespace

double HessianMetric::Density(const Local& l, double scale) const
{
  double mu[3];
  Scaled(l, scale, Opt, mu);
  return std::sqrt(mu[0] * mu[1] * mu[2]);
}

void HessianMetric::Compose(const Local& l, double scale, double m[6]) const
{
  double mu[3];
  Scaled(l, scale, Opt, mu);
  static const int rc[6][2] = { { 0, 0 }, { 0, 1 }, { 0, 2 }, { 1, 1 }, { 1, 2 }, { 2, 2 } };
  for (int i = 0; i < 6; ++i)
  {
    double v = 0;
    for (int k = 0; k < 3; ++k)
    {
      v += mu[k] * l.Vectors[k][rc[i][0]] * l.Vectors[k][rc[i][1]];
    }
    m[i] = v;
  }
}

void HessianMetric::At(const double p[3], double scale, double m[6]) const
{
  Compose(Decompose(p), scale, m);
}
} // namespace art
