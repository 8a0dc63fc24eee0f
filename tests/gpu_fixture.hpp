#pragma once
// One headless OpenGL context per test binary, created on first use; a
// test fails if the driver reported a GL error while it ran.
#include <gtest/gtest.h>

#include "penumbra/gl/context.hpp"

namespace penumbra::testing {

gl::Context& shared_context();

class GpuTest : public ::testing::Test {
 protected:
  void SetUp() override;
  void TearDown() override;

 private:
  int errors_before_ = 0;
};

}  // namespace penumbra::testing
