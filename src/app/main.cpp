#include "app/app.hpp"

int main(int argc, char** argv) {
    return puddle::app::run(argc, argv);
}
