#pragma once
/// \file
/// \brief MoorDyn writes to stdout while reading a file and solving its initial condition: the bench's
///        drivers (moordyn_bench.cpp, moordyn_grounded.cpp) mute file descriptor 1 around those calls.

#include <unistd.h>

#include <cstdio>
#include <iostream>

/// Points stdout at /dev/null for its lifetime (C and C++ streams flushed first); `active` false leaves it
/// alone (moordyn_bench's MDB_VERBOSE).
struct MuteStdout {
  int saved = -1;
  explicit MuteStdout(bool active = true) {
    if (!active) return;
    std::fflush(stdout);
    std::cout.flush();
    saved = dup(1);
    FILE* null = std::fopen("/dev/null", "w");
    dup2(fileno(null), 1);
    std::fclose(null);
  }
  ~MuteStdout() {
    if (saved < 0) return;
    std::fflush(stdout);
    std::cout.flush();
    dup2(saved, 1);
    close(saved);
  }
  MuteStdout(const MuteStdout&) = delete;
  MuteStdout& operator=(const MuteStdout&) = delete;
};
