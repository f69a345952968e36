// Index of node i on a periodic line of n nodes: i wrapped into [0, n), for any sign of i.
#pragma once

namespace slipfront {

inline int periodic_index(long i, int n) {
  return int(((i % n) + n) % n);
}

} // namespace slipfront
