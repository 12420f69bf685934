// A shell prefix that caps how much memory the command after it may allocate, so that an
// allocation from a wrapped or unchecked count fails fast instead of eating the machine.
#pragma once

#include <string>

namespace frictionid::test {

// `ulimit -v` in a normal build. The sanitizers reserve terabytes of address space for shadow
// memory, so there `ulimit -v` would stop the program before main; ASan's own cap on one
// allocation takes its place, and allocator_may_return_null makes an oversized `new` throw
// std::bad_alloc as it would under the ulimit.
inline std::string memory_cap_prefix(long megabytes) {
#ifdef FRICTIONID_SANITIZE
  return "export ASAN_OPTIONS=\"${ASAN_OPTIONS:+$ASAN_OPTIONS:}max_allocation_size_mb=" +
         std::to_string(megabytes) + ":allocator_may_return_null=1\"; ";
#else
  return "ulimit -v " + std::to_string(megabytes * 1000) + "; ";
#endif
}

}  // namespace frictionid::test
