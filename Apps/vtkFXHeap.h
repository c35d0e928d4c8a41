// vtkFXHeap: keeps freed heap memory in the process for the command-line
// tools (vtkfx-render, vtkfx-bench), so that frame times measure rendering
// rather than the kernel's page faults.
//
// Why: llvmpipe bins each frame's primitives into 64 KiB blocks it mallocs,
// and frees them once the frame's draws are rasterised. glibc then hands
// the top of the heap back to the kernel (M_TRIM_THRESHOLD: 128 KiB until
// the free of a large mmapped block raises it), and the next frame faults
// the same pages in again, each one zeroed by the kernel. Under a
// hypervisor a fault is expensive: on the development machine (a VM,
// llvmpipe, 1280x720, the bunny) plain VTK's first 13 frames took 68-89 ms
// and the rest 32-40 ms; vtkFX's directional occlusion took 95-112 ms a frame
// for as long as it ran, and 54-65 ms with the heap kept (its G-buffer
// draw 56-67 -> 17-25 ms). Both VTK's own frames and vtkFX's run in the same
// process, so the ratios the benchmarks print compare like with like
// either way.
//
// Setting the trim threshold also stops glibc from raising its mmap
// threshold as it goes (allocations above it are mapped and unmapped each
// time), so that one is set too, to the largest value glibc would have
// raised it to by itself (32 MiB on 64-bit systems).
//
// Applications on software OpenGL can do the same: mallopt as below, or
// GLIBC_TUNABLES=glibc.malloc.trim_threshold=1073741824:glibc.malloc.mmap_threshold=33554432.
// The tools leave the allocator alone when GLIBC_TUNABLES sets any
// glibc.malloc tunable (the caller chose) or VTKFX_TRIM_HEAP=1 (glibc's
// default behaviour, for comparison).
#ifndef vtkFXHeap_h
#define vtkFXHeap_h

#include <cstdlib>
#include <cstring>
#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace vtkFXHeap
{
// Returns true when it changed the allocator's settings.
inline bool KeepFreedMemory()
{
#if defined(__GLIBC__) && defined(M_TRIM_THRESHOLD) && defined(M_MMAP_THRESHOLD)
  const char* tunables = std::getenv("GLIBC_TUNABLES");
  const char* trim = std::getenv("VTKFX_TRIM_HEAP");
  if ((tunables && std::strstr(tunables, "glibc.malloc.")) || (trim && std::strcmp(trim, "1") == 0))
  {
    return false;
  }
  // 1 GiB: more than any frame's binning takes; memory above it still goes.
  const bool trimSet = mallopt(M_TRIM_THRESHOLD, 1 << 30) == 1;
  return mallopt(M_MMAP_THRESHOLD, 32 << 20) == 1 && trimSet;
#else
  return false;
#endif
}

// The tools' usage note.
constexpr const char* UsageNote =
  "(keeps freed heap memory for steady frame times; VTKFX_TRIM_HEAP=1: glibc's default)\n";

// One line for the tools' output.
inline const char* Describe(bool kept)
{
  return kept ? "heap: freed memory kept in the process (vtkFXHeap.h; VTKFX_TRIM_HEAP=1 to not)"
              : "heap: the allocator's own settings";
}
}

#endif
