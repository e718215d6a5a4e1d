// The rheometer core: simple-shear evaluation and the CSV format `bagnold rheometer` prints.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <sstream>

#include "models/stress/rheometer.hpp"
#include "tests/unit/models/probe.hpp"

namespace bagnold::tests {

TEST(Rheometer, RowHoldsPressureStressRatioAndInertialNumber) {
  const auto model = make_model("skt");
  Material m;
  const auto row = models::shear_rheometer(*model, m, 0.3, 20.0);
  const auto s = probe(*model, m, 0.3, 20.0);
  EXPECT_EQ(row.model, "skt");
  EXPECT_DOUBLE_EQ(row.pressure, s.pressure);
  EXPECT_DOUBLE_EQ(row.shear_stress, s.shear_viscosity * 20.0);
  EXPECT_DOUBLE_EQ(row.stress_ratio, row.shear_stress / row.pressure);
  EXPECT_DOUBLE_EQ(row.inertial_number, 20.0 * m.diameter / std::sqrt(s.pressure / m.density));
  EXPECT_DOUBLE_EQ(row.granular_temperature, s.granular_temperature);
}

TEST(Rheometer, UndefinedQuantitiesAreNaN) {
  Material m;
  // No temperature in the rheology models; no stress ratio or I without pressure.
  EXPECT_TRUE(std::isnan(
      models::shear_rheometer(*make_model("steady-shear"), m, 0.5, 1.0).granular_temperature));
  const auto at_rest = models::shear_rheometer(*make_model("mkt"), m, 0.3, 0.0);
  EXPECT_EQ(at_rest.pressure, 0.0);
  EXPECT_TRUE(std::isnan(at_rest.stress_ratio));
  EXPECT_TRUE(std::isnan(at_rest.inertial_number));
}

TEST(Rheometer, GridIsPhiMajor) {
  const auto rows =
      models::shear_rheometer(*make_model("mkt"), Material{}, {0.1, 0.2}, {1.0, 2.0, 3.0});
  ASSERT_EQ(rows.size(), 6u);
  EXPECT_EQ(rows[2].phi, 0.1);
  EXPECT_EQ(rows[2].shear_rate, 3.0);
  EXPECT_EQ(rows[3].phi, 0.2);
  EXPECT_EQ(rows[3].shear_rate, 1.0);
}

TEST(Rheometer, CsvHasTheExactHeaderEmptyNaNAndRoundTrippingNumbers) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const models::RheometerRow row{"mkt", 1.0 / 3.0, 10.0, 2.5e-7, 1e300, nan, nan, 0.125};
  std::ostringstream out;
  models::write_rheometer_csv(out, {row}, true);
  EXPECT_EQ(out.str(),
            "model,phi,shear_rate,pressure,shear_stress,stress_ratio,granular_temperature,"
            "inertial_number\n"
            "mkt,0.3333333333,10,2.5e-07,1e+300,,,0.125\n");
  std::ostringstream no_header;
  models::write_rheometer_csv(no_header, {row}, false);
  EXPECT_EQ(no_header.str().rfind("mkt,", 0), 0u);
}

}  // namespace bagnold::tests
