#include "io/interruption.hpp"

#include <string>

namespace frictionid {

std::atomic<bool>& interrupt_flag() {
  static std::atomic<bool> flag{false};
  static_assert(std::atomic<bool>::is_always_lock_free);
  return flag;
}

void throw_if_interrupted(const char* what) {
  if (interrupt_flag().load()) throw Interrupted(std::string("interrupted ") + what);
}

}  // namespace frictionid
