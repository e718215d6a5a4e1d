#include <gtest/gtest.h>
#include "models/stress/rheometer.hpp"
TEST(Skt, Smoke) {
  auto m = bagnold::models::stress_registry().create("skt");
  auto r = bagnold::models::shear_rheometer(*m, {}, 0.3, 10.0);
  EXPECT_GT(r.pressure, 0.0);
}
