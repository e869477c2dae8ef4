/* Stand-in for TOPPERS/ASP's t_syslog.h. */
#ifndef STUB_T_SYSLOG_H
#define STUB_T_SYSLOG_H
#define LOG_EMERG 0
#define LOG_ALERT 1
#define LOG_CRIT 2
#define LOG_ERROR 3
#define LOG_WARNING 4
#define LOG_NOTICE 5
#define LOG_INFO 6
#define LOG_DEBUG 7
#ifdef __cplusplus
extern "C" {
#endif
void syslog(unsigned int prio, const char* format, ...);
#ifdef __cplusplus
}
#endif
#endif
