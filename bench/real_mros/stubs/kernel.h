/* Stand-in for TOPPERS/ASP's kernel.h, and for the kernel_cfg.h its
 * configurator writes from an app's app.cfg: only the names mROS v1 uses. */
#ifndef STUB_KERNEL_H
#define STUB_KERNEL_H
#include <stdint.h>
typedef int ER;
typedef int ID;
typedef int PRI;
typedef unsigned int RELTIM;
typedef int TMO;
#define E_OK 0
#define TMIN_TPRI 1
#define TMAX_TPRI 16
#define TMO_FEVR (-1)
#define MAIN_TASK 1
#define SUB_TASK 2
#define PUB_TASK 3
#define XML_SLV_TASK 4
#define XML_MAS_TASK 5
#define USR_TASK1 6
#define USR_TASK2 7
#ifdef __cplusplus
extern "C" {
#endif
ER act_tsk(ID task);
ER sig_sem(ID semaphore);
ER get_tid(ID* task);
ER wup_tsk(ID task);
ER twai_sem(ID semaphore, TMO timeout);
ER slp_tsk(void);
ER wai_sem(ID semaphore);
ER dly_tsk(RELTIM delay);
#ifdef __cplusplus
}
#endif
#endif
