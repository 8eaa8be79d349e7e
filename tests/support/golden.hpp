#pragma once
// Golden images: a whole picture compared with tests/golden/<name>.png.
// Tolerance: mean channel difference at most 1.5 of 255, and at most 1% of pixels off by more than 32
// (room for another llvmpipe or GPU's rounding, not for a changed look). A picture out of tolerance is
// written to test-output/<name>.actual.png. With PUDDLE_UPDATE_GOLDEN set the picture becomes the golden
// image and the test is skipped; look at the pictures before committing them:
//   PUDDLE_UPDATE_GOLDEN=1 ctest --test-dir build -R 'Golden|SeamlessWall'
#include "assets/image.hpp"

namespace puddle::test {

void check_golden(const char* name, const assets::Image& image);

}  // namespace puddle::test
