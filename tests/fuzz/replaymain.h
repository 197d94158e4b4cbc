// The replay of a fuzz target's inputs without libFuzzer (replaymain.cpp).
#pragma once

#include <cstddef>
#include <cstdint>

// A target's entry point: its LLVMFuzzerTestOneInput, renamed.
using FuzzEntry = int (*)(const uint8_t *data, size_t size);

// Runs entry once on every file named in argv[1..] or found below a directory named there.
int replayFuzzInputs(int argc, char **argv, FuzzEntry entry);
