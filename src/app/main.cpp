#include "app/app.hpp"
#include "app/signals.hpp"

int main(int argc, char** argv) {
    puddle::app::block_stop_signals();  // first: a SIGHUP sent while Puddle starts must not end it
    return puddle::app::run(argc, argv);
}
