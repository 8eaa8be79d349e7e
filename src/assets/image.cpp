#include "assets/image.hpp"

namespace puddle::assets {

Image Image::make(int w, int h, PixelFormat f) {
    Image img;
    img.width = w;
    img.height = h;
    img.format = f;
    img.data.assign(std::size_t(w) * h * img.bytes_per_pixel(), 0);
    return img;
}

}  // namespace puddle::assets
