// The entry point of the `gas` program; everything happens in console.cpp.
#include <string>
#include <vector>

#include "program/console.hpp"

int main(int argc, char** argv) {
  return gas::run_console(std::vector<std::string>(argv + 1, argv + argc));
}
