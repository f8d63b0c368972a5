// How the process's allocator treats the large arrays a model holds.
#pragma once

namespace tessera {

// Large arrays (128 KiB and up) are mapped from the system and given back when freed, and the
// heap keeps up to 32 MiB free at its top. Without it glibc raises its mapping threshold to the
// size of the first large array freed, after which a detection pass's arrays come from the heap
// and the holes they leave stay resident: a long run of the 400 x 200 wall then peaked 15% above
// its first pass. Called once by a program's main before it builds a model (the engine itself
// never changes process-wide settings); does nothing on other C libraries.
void tune_allocator();

}  // namespace tessera
