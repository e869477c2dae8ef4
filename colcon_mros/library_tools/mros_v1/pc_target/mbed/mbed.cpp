// SPDX-License-Identifier: BSD-3-Clause
// mbed 2's API on a PC (see mbed.h): pins as a logged output stream and an
// input file, timers and tickers on the PC target's kernel clock.
#include <fcntl.h>
#include <pthread.h>
#include <stdint.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "EthernetInterface.h"
#include "SoftPWM.h"
#include "lwip/netif.h"
#include "mbed.h"
#include "pc_target.h"

namespace {

const int kPinCount = 12 * 16;
const uint64_t kInputPollUs = 10000;

pthread_mutex_t io_lock = PTHREAD_MUTEX_INITIALIZER;
int input_values[kPinCount];
void (*rise_handlers[kPinCount])(void);
void (*fall_handlers[kPinCount])(void);
struct stat inputs_seen;
bool input_poller_started = false;

bool valid(PinName pin) { return pin >= 0 && pin < kPinCount; }

pthread_once_t output_log_opened = PTHREAD_ONCE_INIT;
int output_log = STDERR_FILENO;

void open_output_log() {
  const char *path = getenv("MROS_PC_OUTPUT_LOG");
  if (path != NULL && path[0] != '\0') output_log = open(path, O_WRONLY | O_APPEND | O_CREAT, 0644);
}

struct OutputChange {
  PinName pin;
  const char *value;
};

// One line a change, written whole (O_APPEND), so a test can read it as it comes.
void write_output_change(void *change_pointer) {
  const OutputChange *change = static_cast<const OutputChange *>(change_pointer);
  char line[64];
  int length = snprintf(line, sizeof line, "P%d_%d %s\n", change->pin / 16, change->pin % 16,
                        change->value);
  pthread_once(&output_log_opened, open_output_log);
  if (output_log < 0) return;
  if (write(output_log, line, static_cast<size_t>(length)) < 0) {
    // An output nobody can read is not the app's problem.
  }
}

// On the host stack, as the board writes a pin without the task's stack.
void log_output(PinName pin, const char *value) {
  OutputChange change = {pin, value};
  pc_on_host_stack(write_output_change, &change);
}

// "P6_0 1" or "P6_0=1": the pin number, or -1.
int parse_input_line(const char *line, int *value) {
  int port = 0, bit = 0, consumed = 0;
  if (sscanf(line, " P%d_%d%n", &port, &bit, &consumed) != 2) return -1;
  if (port < 0 || port > 11 || bit < 0 || bit > 15) return -1;
  const char *rest = line + consumed;
  while (*rest == ' ' || *rest == '\t' || *rest == '=') rest++;
  if (sscanf(rest, "%d", value) != 1) return -1;
  *value = *value != 0;
  return port * 16 + bit;
}

void call_rise(void *pin) { rise_handlers[reinterpret_cast<intptr_t>(pin)](); }
void call_fall(void *pin) { fall_handlers[reinterpret_cast<intptr_t>(pin)](); }

// Reads the input file again if it changed; an edge on a pin with an
// InterruptIn handler raises it.
void refresh_inputs() {
  const char *path = getenv("MROS_PC_INPUTS");
  if (path == NULL || path[0] == '\0') return;
  pthread_mutex_lock(&io_lock);
  struct stat now;
  bool changed = stat(path, &now) == 0 &&
                 (now.st_mtim.tv_sec != inputs_seen.st_mtim.tv_sec ||
                  now.st_mtim.tv_nsec != inputs_seen.st_mtim.tv_nsec ||
                  now.st_size != inputs_seen.st_size);
  int values[kPinCount] = {0};
  FILE *file = changed ? fopen(path, "r") : NULL;
  bool reread = file != NULL;
  if (reread) {
    inputs_seen = now;
    char line[128];
    while (fgets(line, sizeof line, file) != NULL) {
      int value = 0;
      int pin = parse_input_line(line, &value);
      if (pin >= 0) values[pin] = value;
    }
    fclose(file);
  }
  int rises[kPinCount], falls[kPinCount];
  int rise_count = 0, fall_count = 0;
  for (int pin = 0; reread && pin < kPinCount; pin++) {
    if (values[pin] == input_values[pin]) continue;
    input_values[pin] = values[pin];
    if (values[pin] && rise_handlers[pin] != NULL) rises[rise_count++] = pin;
    if (!values[pin] && fall_handlers[pin] != NULL) falls[fall_count++] = pin;
  }
  pthread_mutex_unlock(&io_lock);
  // Raised only now: raising is a switch point, and no switch may happen
  // while io_lock is held.
  for (int index = 0; index < rise_count; index++) {
    pc_raise_interrupt(call_rise, reinterpret_cast<void *>(static_cast<intptr_t>(rises[index])));
  }
  for (int index = 0; index < fall_count; index++) {
    pc_raise_interrupt(call_fall, reinterpret_cast<void *>(static_cast<intptr_t>(falls[index])));
  }
}

void poll_inputs(void *) { refresh_inputs(); }

void start_input_poller() {
  pthread_mutex_lock(&io_lock);
  bool start = !input_poller_started && getenv("MROS_PC_INPUTS") != NULL;
  input_poller_started = input_poller_started || start;
  pthread_mutex_unlock(&io_lock);
  if (start) pc_timer_start(poll_inputs, NULL, kInputPollUs, kInputPollUs);
}

int read_input(PinName pin) {
  pc_on_host_stack(poll_inputs, NULL);
  pc_dispatch_point();
  if (!valid(pin)) return 0;
  pthread_mutex_lock(&io_lock);
  int value = input_values[pin];
  pthread_mutex_unlock(&io_lock);
  return value;
}

void spin_us(uint64_t microseconds) {
  uint64_t until = pc_now_us() + microseconds;
  while (pc_now_us() < until) {
  }
}

}  // namespace

extern "C" void mbed_mac_address(char *mac) {
  static const char address[6] = {0x00, 0x02, static_cast<char>(0xf7), static_cast<char>(0xf0), 0x00, 0x01};
  memcpy(mac, address, sizeof address);
}

namespace mbed {

void wait(float seconds) {
  if (seconds <= 0) return;
  if (sns_ctx()) {
    spin_us(static_cast<uint64_t>(seconds * 1e6f));
  } else {
    dly_tsk(static_cast<RELTIM>(ceilf(seconds * 1000.0f)));
  }
}

void wait_ms(int milliseconds) { wait(milliseconds / 1000.0f); }

void wait_us(int microseconds) {
  if (microseconds > 0) spin_us(static_cast<uint64_t>(microseconds));
}

DigitalOut::DigitalOut(PinName pin) : pin_(pin), value_(0) {}

DigitalOut::DigitalOut(PinName pin, int value) : pin_(pin), value_(value != 0) {}

void DigitalOut::write(int value) {
  int level = value != 0;
  if (level != value_) log_output(pin_, level ? "1" : "0");
  value_ = level;
  pc_dispatch_point();
}

int DigitalOut::read() { return value_; }

DigitalOut &DigitalOut::operator=(int value) {
  write(value);
  return *this;
}

DigitalOut &DigitalOut::operator=(DigitalOut &other) {
  write(other.read());
  return *this;
}

DigitalOut::operator int() { return read(); }

DigitalIn::DigitalIn(PinName pin) : pin_(pin) {}

DigitalIn::DigitalIn(PinName pin, PinMode) : pin_(pin) {}

int DigitalIn::read() { return read_input(pin_); }

void DigitalIn::mode(PinMode) {}

DigitalIn::operator int() { return read(); }

InterruptIn::InterruptIn(PinName pin) : pin_(pin) {}

int InterruptIn::read() { return read_input(pin_); }

InterruptIn::operator int() { return read(); }

void InterruptIn::rise(void (*handler)(void)) {
  if (!valid(pin_)) return;
  rise_handlers[pin_] = handler;
  start_input_poller();
}

void InterruptIn::fall(void (*handler)(void)) {
  if (!valid(pin_)) return;
  fall_handlers[pin_] = handler;
  start_input_poller();
}

void InterruptIn::mode(PinMode) {}

void InterruptIn::enable_irq() {}

void InterruptIn::disable_irq() {}

Timer::Timer() : started_us_(0), elapsed_us_(0), running_(false) {}

void Timer::start() {
  if (running_) return;
  started_us_ = pc_now_us();
  running_ = true;
}

void Timer::stop() {
  if (!running_) return;
  elapsed_us_ += pc_now_us() - started_us_;
  running_ = false;
}

void Timer::reset() {
  elapsed_us_ = 0;
  started_us_ = pc_now_us();
}

int Timer::read_us() {
  uint64_t total = elapsed_us_ + (running_ ? pc_now_us() - started_us_ : 0);
  return static_cast<int>(total);
}

int Timer::read_ms() { return read_us() / 1000; }

float Timer::read() { return read_us() / 1e6f; }

Timer::operator float() { return read(); }

Ticker::Ticker() : handler_(NULL), timer_(-1) {}

Ticker::~Ticker() { detach(); }

// Interrupt level: no task runs, so the ticker cannot be detached or
// destroyed while its handler is called.
void Ticker::call(void *ticker) { static_cast<Ticker *>(ticker)->handler_(); }

void Ticker::start(void (*handler)(void), uint64_t first_us, uint64_t period_us) {
  detach();
  handler_ = handler;
  timer_ = pc_timer_start(call, this, first_us, period_us);
}

void Ticker::attach(void (*handler)(void), float seconds) {
  uint64_t period = static_cast<uint64_t>(seconds * 1e6f);
  start(handler, period, period);
}

void Ticker::attach_us(void (*handler)(void), uint64_t microseconds) {
  start(handler, microseconds, microseconds);
}

void Ticker::detach() {
  if (timer_ >= 0) pc_timer_stop(timer_);
  timer_ = -1;
}

void Timeout::attach(void (*handler)(void), float seconds) {
  start(handler, static_cast<uint64_t>(seconds * 1e6f), 0);
}

void Timeout::attach_us(void (*handler)(void), uint64_t microseconds) {
  start(handler, microseconds, 0);
}

}  // namespace mbed

SoftPWM::SoftPWM(PinName pin, bool) : pin_(pin), duty_(0.0f), period_us_(20000) {}

void SoftPWM::write(float duty) {
  float clamped = duty < 0.0f ? 0.0f : (duty > 1.0f ? 1.0f : duty);
  if (clamped != duty_) {
    char text[32];
    snprintf(text, sizeof text, "%g", static_cast<double>(clamped));
    log_output(pin_, text);
  }
  duty_ = clamped;
  pc_dispatch_point();
}

float SoftPWM::read() { return duty_; }

void SoftPWM::period(float seconds) { period_us_ = static_cast<int>(seconds * 1e6f); }

void SoftPWM::period_ms(int milliseconds) { period_us_ = milliseconds * 1000; }

void SoftPWM::period_us(int microseconds) { period_us_ = microseconds; }

void SoftPWM::pulsewidth(float seconds) { write(seconds * 1e6f / period_us_); }

void SoftPWM::pulsewidth_ms(int milliseconds) { write(milliseconds * 1000.0f / period_us_); }

void SoftPWM::pulsewidth_us(int microseconds) { write(static_cast<float>(microseconds) / period_us_); }

void SoftPWM::start() {}

void SoftPWM::stop() { write(0.0f); }

SoftPWM &SoftPWM::operator=(float duty) {
  write(duty);
  return *this;
}

SoftPWM &SoftPWM::operator=(SoftPWM &other) {
  write(other.read());
  return *this;
}

SoftPWM::operator float() { return read(); }

namespace {
char *copy_of(const char *text) {
  static char buffers[4][20];
  static int next = 0;
  char *buffer = buffers[next++ % 4];
  snprintf(buffer, sizeof buffers[0], "%s", text);
  return buffer;
}
}  // namespace

int EthernetInterface::init() { return 0; }

int EthernetInterface::init(const char *, const char *, const char *) { return 0; }

int EthernetInterface::connect(unsigned int) { return 0; }

int EthernetInterface::disconnect() { return 0; }

char *EthernetInterface::getMACAddress() { return copy_of("00:02:f7:f0:00:01"); }

char *EthernetInterface::getIPAddress() { return copy_of(pc_node_address()); }

char *EthernetInterface::getGateway() { return copy_of("0.0.0.0"); }

char *EthernetInterface::getNetworkMask() { return copy_of("255.0.0.0"); }
