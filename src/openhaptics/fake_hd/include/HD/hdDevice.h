/* Device functions of the HD API: initialisation, frames, state queries and commands, errors
 * and calibration. Only the functions the fake implements are declared. */
#ifndef COSMEMS_FAKE_HD_DEVICE_H
#define COSMEMS_FAKE_HD_DEVICE_H

#include "HD/hdDefines.h"
#include "HD/hdExport.h"

#ifdef __cplusplus
extern "C" {
#endif

HDAPI HHD HDAPIENTRY hdInitDevice(HDstring pConfigName);
HDAPI void HDAPIENTRY hdMakeCurrentDevice(HHD hHD);
HDAPI void HDAPIENTRY hdDisableDevice(HHD hHD);
HDAPI HHD HDAPIENTRY hdGetCurrentDevice(void);

HDAPI void HDAPIENTRY hdBeginFrame(HHD hHD);
HDAPI void HDAPIENTRY hdEndFrame(HHD hHD);

HDAPI HDErrorInfo HDAPIENTRY hdGetError(void);
HDAPI HDstring HDAPIENTRY hdGetErrorString(HDerror errorCode);

HDAPI void HDAPIENTRY hdEnable(HDenum cap);
HDAPI void HDAPIENTRY hdDisable(HDenum cap);
HDAPI HDboolean HDAPIENTRY hdIsEnabled(HDenum cap);

HDAPI void HDAPIENTRY hdGetBooleanv(HDenum pname, HDboolean* params);
HDAPI void HDAPIENTRY hdGetIntegerv(HDenum pname, HDint* params);
HDAPI void HDAPIENTRY hdGetFloatv(HDenum pname, HDfloat* params);
HDAPI void HDAPIENTRY hdGetDoublev(HDenum pname, HDdouble* params);
HDAPI void HDAPIENTRY hdGetLongv(HDenum pname, HDlong* params);
HDAPI HDstring HDAPIENTRY hdGetString(HDenum pname);

HDAPI void HDAPIENTRY hdSetBooleanv(HDenum pname, const HDboolean* params);
HDAPI void HDAPIENTRY hdSetIntegerv(HDenum pname, const HDint* params);
HDAPI void HDAPIENTRY hdSetFloatv(HDenum pname, const HDfloat* params);
HDAPI void HDAPIENTRY hdSetDoublev(HDenum pname, const HDdouble* params);
HDAPI void HDAPIENTRY hdSetLongv(HDenum pname, const HDlong* params);

HDAPI HDenum HDAPIENTRY hdCheckCalibration(void);
HDAPI HDenum HDAPIENTRY hdCheckCalibrationStyle(void);
HDAPI void HDAPIENTRY hdUpdateCalibration(HDenum style);

#ifdef __cplusplus
}
#endif

#endif
