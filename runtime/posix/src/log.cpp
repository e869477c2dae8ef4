// log.cpp: output of the ROS_* logging macros, formatted like roscpp's
// console ("[ INFO] [1700000000.123456789]: text").
#include "mros_log.h"

#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <mutex>

namespace mros {
namespace log {

namespace {
const char* const kLevelNames[] = {"DEBUG", " INFO", " WARN", "ERROR", "FATAL"};
std::mutex output_mutex;  // keeps lines of concurrent threads whole
}  // namespace

void print(Level level, const char* format, ...) {
  timespec now;
  clock_gettime(CLOCK_REALTIME, &now);
  FILE* stream = level >= kWarn ? stderr : stdout;
  std::lock_guard<std::mutex> lock(output_mutex);
  std::fprintf(stream, "[%s] [%ld.%09ld]: ", kLevelNames[level], static_cast<long>(now.tv_sec),
               now.tv_nsec);
  va_list args;
  va_start(args, format);
  std::vfprintf(stream, format, args);
  va_end(args);
  std::fputc('\n', stream);
  std::fflush(stream);
}

}  // namespace log
}  // namespace mros
