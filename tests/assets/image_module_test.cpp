#include "assets/image_module.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace puddle::assets {
namespace {

namespace fs = std::filesystem;

// The test executable sits in build/tests/, so without the override the module is found the way the
// installed /usr/bin/puddle finds /usr/lib/puddle/: in ../lib/puddle/.
TEST(ImageModule, PathIsTheOverrideElseLibPuddleBesideTheExecutablesFolder) {
    ::unsetenv(image_module_env);
    const fs::path found = image_module_path();
    EXPECT_EQ(found, fs::path(PUDDLE_BUILD_DIR) / "lib" / "puddle" / "libpuddle-images.so");
    EXPECT_TRUE(fs::exists(found)) << found << ": the build puts the module where puddle looks";

    ::setenv(image_module_env, "/opt/elsewhere/libpuddle-images.so", 1);
    EXPECT_EQ(image_module_path(), "/opt/elsewhere/libpuddle-images.so");
    ::setenv(image_module_env, "", 1);  // empty is unset
    EXPECT_EQ(fs::path(image_module_path()), found);
    ::unsetenv(image_module_env);
}

TEST(ImageModule, LoadsAndSpeaksThisInterfaceVersion) {
    auto module = image_module();
    ASSERT_TRUE(module.ok()) << module.error().message;
    EXPECT_EQ((*module)->abi_version, PUDDLE_IMAGE_MODULE_ABI_VERSION);
    EXPECT_NE((*module)->read, nullptr);
    EXPECT_NE((*module)->probe, nullptr) << "version 2 reads headers alone";
}

}  // namespace
}  // namespace puddle::assets
