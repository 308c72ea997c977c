// SymmetricEigen3: eigenvalues and eigenvectors of a symmetric 3 x 3 matrix by cyclic Jacobi
// rotations (Golub & Van Loan, Matrix Computations, section 8.5), and the tensors built back
// from them. Packed order m11 m12 m13 m22 m23 m33, as MMG's API takes a metric.
#ifndef art_SymmetricEigen3_h
#define art_SymmetricEigen3_h

#include <cmath>

namespace art
{
struct SymmetricEigen3
{
  double Values[3];     ///< eigenvalues, in no particular order
  double Vectors[3][3]; ///< Vectors[k] is the unit eigenvector of Values[k]

  /// Decomposes the packed symmetric matrix m (m11 m12 m13 m22 m23 m33).
  explicit SymmetricEigen3(const double m[6])
  {
    double a[3][3] = { { m[0], m[1], m[2] }, { m[1], m[3], m[4] }, { m[2], m[4], m[5] } };
    double v[3][3] = { { 1, 0, 0 }, { 0, 1, 0 }, { 0, 0, 1 } };
    for (int sweep = 0; sweep < 12; ++sweep)
    {
      const double off = a[0][1] * a[0][1] + a[0][2] * a[0][2] + a[1][2] * a[1][2];
      const double diag = a[0][0] * a[0][0] + a[1][1] * a[1][1] + a[2][2] * a[2][2];
      if (off <= 1e-30 * diag || off == 0)
      {
        break;
      }
      for (int p = 0; p < 2; ++p)
      {
        for (int q = p + 1; q < 3; ++q)
        {
          Rotate(a, v, p, q);
        }
      }
    }
    for (int k = 0; k < 3; ++k)
    {
      Values[k] = a[k][k];
      for (int d = 0; d < 3; ++d)
      {
        Vectors[k][d] = v[d][k];
      }
    }
  }

  /// sum_k l[k] e_k e_k^T, packed.
  void Compose(const double l[3], double out[6]) const
  {
    static const int rc[6][2] = { { 0, 0 }, { 0, 1 }, { 0, 2 }, { 1, 1 }, { 1, 2 }, { 2, 2 } };
    for (int i = 0; i < 6; ++i)
    {
      double s = 0;
      for (int k = 0; k < 3; ++k)
      {
        s += l[k] * Vectors[k][rc[i][0]] * Vectors[k][rc[i][1]];
      }
      out[i] = s;
    }
  }

private:
  static void Rotate(double a[3][3], double v[3][3], int p, int q)
  {
    if (a[p][q] == 0)
    {
      return;
    }
    const double theta = (a[q][q] - a[p][p]) / (2 * a[p][q]);
    const double t = (theta >= 0 ? 1.0 : -1.0) / (std::fabs(theta) + std::sqrt(theta * theta + 1));
    const double c = 1 / std::sqrt(t * t + 1), s = t * c;
    for (int k = 0; k < 3; ++k)
    {
      const double akp = a[k][p], akq = a[k][q];
      a[k][p] = c * akp - s * akq;
      a[k][q] = s * akp + c * akq;
    }
    for (int k = 0; k < 3; ++k)
    {
      const double apk = a[p][k], aqk = a[q][k];
      a[p][k] = c * apk - s * aqk;
      a[q][k] = s * apk + c * aqk;
    }
    for (int k = 0; k < 3; ++k)
    {
      const double vkp = v[k][p], vkq = v[k][q];
      v[k][p] = c * vkp - s * vkq;
      v[k][q] = s * vkp + c * vkq;
    }
  }
};
} // namespace art

#endif
