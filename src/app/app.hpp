#pragma once
// The puddle program: options -> parameters -> engine -> frame loop. Returns the process exit code.
namespace puddle::app {
int run(int argc, const char* const* argv);
}
