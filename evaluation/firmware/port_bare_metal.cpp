// SPDX-License-Identifier: BSD-3-Clause
// The board's port for a bare-metal Cortex-M, built for its size: the app
// runs (Fig. 6 publishes on every tick), and what it would send is counted.
// The relays and Fig. 7 are linked in through the app's topic table.
#include "board.h"

namespace {

volatile uint32_t bytes_sent;
volatile uint32_t lines_logged;

}  // namespace

namespace board {

void send(int, const uint8_t*, uint32_t size) { bytes_sent = bytes_sent + size; }

void log(const char*) { lines_logged = lines_logged + 1; }

}  // namespace board

int main() {
  board::start();
  for (;;) {
    board::tick();
  }
}
