/* Scheduler functions and types of the HD API: one servo thread per process runs the scheduled
 * callbacks once a tick, highest priority first. */
#ifndef COSMEMS_FAKE_HD_SCHEDULER_H
#define COSMEMS_FAKE_HD_SCHEDULER_H

#include "HD/hdDefines.h"
#include "HD/hdExport.h"

#ifdef __cplusplus
extern "C" {
#endif

typedef unsigned int HDCallbackCode;
#define HD_CALLBACK_DONE 0
#define HD_CALLBACK_CONTINUE 1

/* 64 bits on LP64 Linux: storing one in a 32-bit integer loses the operation. */
typedef unsigned long HDSchedulerHandle;

typedef HDCallbackCode(HDCALLBACK* HDSchedulerCallback)(void* pUserData);

typedef unsigned int HDWaitCode;
#define HD_WAIT_CHECK_STATUS 0
#define HD_WAIT_INFINITE 1

HDAPI void HDAPIENTRY hdStartScheduler(void);
HDAPI void HDAPIENTRY hdStopScheduler(void);
HDAPI void HDAPIENTRY hdSetSchedulerRate(HDulong nRate);
HDAPI void HDAPIENTRY hdScheduleSynchronous(HDSchedulerCallback pCallback, void* pUserData,
                                            HDushort nPriority);
HDAPI HDSchedulerHandle HDAPIENTRY hdScheduleAsynchronous(HDSchedulerCallback pCallback,
                                                          void* pUserData, HDushort nPriority);
HDAPI void HDAPIENTRY hdUnschedule(HDSchedulerHandle hHandle);
HDAPI HDboolean HDAPIENTRY hdWaitForCompletion(HDSchedulerHandle hHandle, HDWaitCode param);
HDAPI HDdouble HDAPIENTRY hdGetSchedulerTimeStamp(void);

#ifdef __cplusplus
}
#endif

#endif
