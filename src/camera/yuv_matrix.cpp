#include "camera/yuv_matrix.hpp"

namespace puddle::camera {

YuvToRgb yuv_to_rgb(YuvMatrix m, bool full_range) {
    // Luma weights of red and blue (ITU-R BT.601, BT.709, BT.2020); green takes the rest.
    float kr = 0.299f, kb = 0.114f;
    if (m == YuvMatrix::Bt709) kr = 0.2126f, kb = 0.0722f;
    if (m == YuvMatrix::Bt2020) kr = 0.2627f, kb = 0.0593f;
    const float kg = 1.0f - kr - kb;
    // Limited range: Y 16..235 (219 steps), Cb/Cr 16..240 (224 steps) around 128.
    const float y_scale = full_range ? 1.0f : 255.0f / 219.0f;
    const float c_scale = full_range ? 255.0f / 255.0f : 255.0f / 224.0f;
    const float cr_r = 2.0f * (1.0f - kr) * c_scale;
    const float cb_b = 2.0f * (1.0f - kb) * c_scale;
    const float cb_g = -2.0f * kb * (1.0f - kb) / kg * c_scale;
    const float cr_g = -2.0f * kr * (1.0f - kr) / kg * c_scale;
    YuvToRgb out;
    // Column-major: columns are the Y, Cb and Cr contributions.
    out.matrix = glm::mat3(glm::vec3(y_scale, y_scale, y_scale), glm::vec3(0.0f, cb_g, cb_b),
                           glm::vec3(cr_r, cr_g, 0.0f));
    out.offset = glm::vec3(full_range ? 0.0f : 16.0f / 255.0f, 128.0f / 255.0f, 128.0f / 255.0f);
    return out;
}

}  // namespace puddle::camera
