// A hint for large buffers that are about to be written from start to end, such as the columns
// of a dataset being read: back them with transparent huge pages. Where the kernel grants those
// only on request (the "madvise" setting), 100 MB of new rows otherwise cost 25,000 page faults,
// and on virtual machines where a fault takes 10-15 us that is more than parsing the file.
#pragma once

#include <cstddef>

namespace frictionid::io_detail {

// Advises huge pages for the whole 2 MiB pages inside [data, data + bytes); smaller buffers are
// left alone. The contents do not change, and where the hint is not supported nothing happens.
void advise_huge_pages(const void* data, std::size_t bytes);

}  // namespace frictionid::io_detail
