// The suite's main: the libraries' error handling is set once, as the CLI's main sets it, before any test.
#include <gtest/gtest.h>

#include "dpdrng/study/library_init.hpp"

namespace {

class LibrariesEnvironment : public ::testing::Environment {
 public:
  void SetUp() override { dpdrng::study::init_libraries(); }
};

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  ::testing::AddGlobalTestEnvironment(new LibrariesEnvironment);  // GoogleTest owns and deletes it
  return RUN_ALL_TESTS();
}
