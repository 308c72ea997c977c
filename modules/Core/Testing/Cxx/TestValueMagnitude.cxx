#include "ValueMagnitude.h"

#include <gtest/gtest.h>

#include <string>

using art::RequireComputableRange;

// Ranges whose squares stay finite and non-zero pass; 1e300 and denormals are named with the way out.
TEST(ValueMagnitude, RefusesRangesWhoseSquaresOverflowOrVanish)
{
  EXPECT_NO_THROW(RequireComputableRange(-1024, 3071, "ct.mha"));
  EXPECT_NO_THROW(RequireComputableRange(0, 0, "zeros.vti"));          // all zero: exact, nothing squared away
  EXPECT_NO_THROW(RequireComputableRange(1e-40, 2e-40, "float.vti")); // float denormals are normal doubles
  EXPECT_NO_THROW(RequireComputableRange(-1e150, 1e150, "edge.vti"));
  EXPECT_NO_THROW(RequireComputableRange(0, 1e-149, "small.vti"));
  EXPECT_THROW(RequireComputableRange(-1e300, 5, "big.vti"), art::Error);
  EXPECT_THROW(RequireComputableRange(0, 1e-200, "tiny.vti"), art::Error);
  try
  {
    RequireComputableRange(1e-310, 4e-310, "d.vti");
    FAIL() << "denormal range accepted";
  }
  catch (const art::Error& e)
  {
    EXPECT_EQ(std::string(e.what()), "d.vti: the scalars' range 1e-310 .. 4e-310 lies below 1e-150 in magnitude: "
                                     "rendering and reducing compute with squares of the values, which vanish to 0; "
                                     "rescale them first (e.g. vtkImageShiftScale, ParaView's Calculator, or numpy)");
  }
}
