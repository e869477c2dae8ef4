/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * TOPPERS/ASP's kernel API on a PC: the types, constants and service calls
 * that mROS v1 and its apps use, run by kernel*.c with ASP's
 * scheduling (one task at a time, highest priority first, FIFO within a
 * priority, a switch only inside a service call).
 */
#ifndef MROS_PC_TARGET_KERNEL_H
#define MROS_PC_TARGET_KERNEL_H

#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

typedef int bool_t;
typedef signed int int_t;
typedef unsigned int uint_t;
typedef int ER;
typedef int ID;
typedef int PRI;
typedef int ER_UINT;
typedef uint_t ATR;
typedef uint_t STAT;
typedef uint_t RELTIM;
typedef uint32_t SYSTIM;
typedef int TMO;
typedef intptr_t EXINF;
typedef void (*TASK)(intptr_t exinf);
typedef void (*CYCHDR)(intptr_t exinf);
typedef void (*INIRTN)(intptr_t exinf);

#ifndef true
#define true 1
#define false 0
#endif

#define E_OK 0
#define E_SYS (-5)
#define E_NOSPT (-9)
#define E_PAR (-17)
#define E_ID (-18)
#define E_CTX (-25)
#define E_OBJ (-41)
#define E_QOVR (-43)
#define E_RLWAI (-49)
#define E_TMOUT (-50)

#define TA_NULL 0U
#define TA_ACT 0x01U
#define TA_STA 0x02U
#define TA_TPRI 0x01U

#define TSK_SELF 0
#define TSK_NONE 0
#define TPRI_SELF 0
#define TPRI_INI 0
#define TMIN_TPRI 1
#define TMAX_TPRI 16
#define TMAX_ACTCNT 1
#define TMAX_WUPCNT 1

#define TMO_POL 0
#define TMO_FEVR (-1)

#define UINT_C(val) (val##U)
#define ULONG_C(val) (val##UL)

ER act_tsk(ID tskid);
ER iact_tsk(ID tskid);
ER_UINT can_act(ID tskid);
ER ext_tsk(void);
ER get_tid(ID *p_tskid);
ER iget_tid(ID *p_tskid);
ER get_pri(ID tskid, PRI *p_tskpri);
ER chg_pri(ID tskid, PRI tskpri);
ER rot_rdq(PRI tskpri);
ER slp_tsk(void);
ER tslp_tsk(TMO tmout);
ER wup_tsk(ID tskid);
ER iwup_tsk(ID tskid);
ER_UINT can_wup(ID tskid);
ER dly_tsk(RELTIM dlytim);
ER sig_sem(ID semid);
ER isig_sem(ID semid);
ER wai_sem(ID semid);
ER pol_sem(ID semid);
ER twai_sem(ID semid, TMO tmout);
ER sta_cyc(ID cycid);
ER stp_cyc(ID cycid);
ER get_tim(SYSTIM *p_systim);
bool_t sns_ctx(void);

#ifdef __cplusplus
}
#endif

/* The library's ros.cpp names task IDs (SUB_TASK) with nothing but this
 * header included, as it does on GR-PEACH's ASP: the IDs the configurator
 * wrote for the app come with it. */
#if defined(__has_include)
#if __has_include("kernel_cfg.h")
#include "kernel_cfg.h"
#endif
#endif

#endif /* MROS_PC_TARGET_KERNEL_H */
