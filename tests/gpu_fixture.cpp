#include "gpu_fixture.hpp"

#include <memory>

namespace penumbra::testing {

gl::Context& shared_context() {
  static std::unique_ptr<gl::Context> context = gl::Context::create_headless({.debug = true});
  return *context;
}

void GpuTest::SetUp() {
  errors_before_ = shared_context().error_count();
}

void GpuTest::TearDown() {
  EXPECT_EQ(shared_context().error_count(), errors_before_)
      << "OpenGL reported an error: " << shared_context().last_error();
}

}  // namespace penumbra::testing
