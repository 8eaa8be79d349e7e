// Linked into each layer's link check (CMakeLists.txt, puddle_layer): a shared object made of the whole
// layer and only the libraries it may use, with --no-undefined, so that a call into any other layer is a
// link error. The object itself is never loaded; this file only gives the linker a source to start from.
namespace puddle {
extern const int layer_link_check = 1;
}
