// How the tools' heap treats freed memory (glibc malloc).
#pragma once

namespace qm::tools {

/// Freed memory stays in the heap for reuse instead of going back to the kernel:
/// blocks up to 32 MB (glibc's largest threshold) come from the heap, which grows
/// in 256 MB steps and is trimmed only above 1 GB free. The stages allocate and
/// free large arrays one after another; returning them made page faults most of
/// the forms stage on a virtual machine (bunny-open-large: 22.6 s -> 16.5 s for
/// the whole job), for about 10% more peak memory. Call first thing in main.
void keep_freed_memory();

}  // namespace qm::tools
