// mros_log.h: the mROS v1 logging macros (ROS_DEBUG ... ROS_FATAL, printf
// style) for the POSIX target. Lines go to stdout (DEBUG, INFO) or stderr
// (WARN and worse), each stamped like roscpp's console output and flushed at
// once, so a test or a terminal sees them while the node runs.
#ifndef MROS_LOG_H
#define MROS_LOG_H

namespace mros {
namespace log {

enum Level { kDebug, kInfo, kWarn, kError, kFatal };

void print(Level level, const char* format, ...) __attribute__((format(printf, 2, 3)));

}  // namespace log
}  // namespace mros

#ifdef MROS_LOG_DISABLE_DEBUG
#define ROS_DEBUG(...)
#else
#define ROS_DEBUG(...) ::mros::log::print(::mros::log::kDebug, __VA_ARGS__)
#endif

#ifdef MROS_LOG_DISABLE_INFO
#define ROS_INFO(...)
#else
#define ROS_INFO(...) ::mros::log::print(::mros::log::kInfo, __VA_ARGS__)
#endif

#ifdef MROS_LOG_DISABLE_WARN
#define ROS_WARN(...)
#else
#define ROS_WARN(...) ::mros::log::print(::mros::log::kWarn, __VA_ARGS__)
#endif

#ifdef MROS_LOG_DISABLE_ERROR
#define ROS_ERROR(...)
#else
#define ROS_ERROR(...) ::mros::log::print(::mros::log::kError, __VA_ARGS__)
#endif

#ifdef MROS_LOG_DISABLE_FATAL
#define ROS_FATAL(...)
#else
#define ROS_FATAL(...) ::mros::log::print(::mros::log::kFatal, __VA_ARGS__)
#endif

#endif  // MROS_LOG_H
