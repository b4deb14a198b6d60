// How much memory this process may still take, in bytes: the least of what the machine has
// available (MemAvailable), what the process's address-space limit (ulimit -v) leaves beside what
// it maps already, and what its control group's limit (a container's or a job's cap) leaves beside
// what the group uses. Linux; elsewhere no limit is known (infinity).
#ifndef ShrinkWrap_Memory_h
#define ShrinkWrap_Memory_h

namespace shrinkwrap
{

double availableMemory();

} // namespace shrinkwrap

#endif
