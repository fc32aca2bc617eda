/* Error helpers of the HD utility library: classify an HD error and print it. */
#ifndef COSMEMS_FAKE_HDU_ERROR_H
#define COSMEMS_FAKE_HDU_ERROR_H

#include <stdio.h>

#include "HD/hdDefines.h"

#ifdef __cplusplus
extern "C" {
#endif

/* True for the errors after which the device refused a force but the loop may go on: warm
 * motors, a force or velocity above the limit, a generic force error. */
HDboolean hduIsForceError(const HDErrorInfo* error);
/* True for the errors after which the servo loop cannot go on: the link, its configuration or
 * the timer failed, or the scheduler rejected an operation. */
HDboolean hduIsSchedulerError(const HDErrorInfo* error);
/* Writes the error, its description, device and internal code, after `message`. */
void hduPrintError(FILE* stream, const HDErrorInfo* error, const char* message);

#ifdef __cplusplus
}
#endif

#endif
