// Descriptions of HD error codes, and the HDU helpers that classify and print errors.
#include <HDU/hduError.h>

#include <cstdio>

#include "fake_world.hpp"

namespace cosmems::fake_hd {

extern "C" {

HDstring hdGetErrorString(HDerror errorCode) {
  switch (errorCode) {
    case HD_SUCCESS:
      return "no error";
    case HD_INVALID_ENUM:
      return "unknown parameter or capability";
    case HD_INVALID_VALUE:
      return "value out of range";
    case HD_INVALID_OPERATION:
      return "operation not allowed in this state";
    case HD_INVALID_INPUT_TYPE:
      return "parameter read with the wrong type";
    case HD_BAD_HANDLE:
      return "no device with this handle";
    case HD_WARM_MOTORS:
      return "motors too warm: force output refused";
    case HD_EXCEEDED_MAX_FORCE:
      return "force above the device's maximum";
    case HD_EXCEEDED_MAX_FORCE_IMPULSE:
      return "force change above the impulse limit";
    case HD_EXCEEDED_MAX_VELOCITY:
      return "velocity above the software limit";
    case HD_FORCE_ERROR:
      return "force error";
    case HD_DEVICE_FAULT:
      return "device fault: the device could not be initialised";
    case HD_DEVICE_ALREADY_INITIATED:
      return "device already initialised";
    case HD_COMM_ERROR:
      return "communication with the device failed";
    case HD_COMM_CONFIG_ERROR:
      return "communication configuration error";
    case HD_TIMER_ERROR:
      return "servo timer error";
    case HD_ILLEGAL_BEGIN:
      return "frame begun twice in one tick";
    case HD_ILLEGAL_END:
      return "frame ended without a begin";
    case HD_FRAME_ERROR:
      return "frame error";
    case HD_INVALID_PRIORITY:
      return "invalid scheduler priority";
    case HD_SCHEDULER_FULL:
      return "too many scheduler operations";
    case HD_INVALID_LICENSE:
      return "invalid licence";
    default:
      return "unknown error";
  }
}

HDboolean hduIsForceError(const HDErrorInfo* error) {
  switch (error->errorCode) {
    case HD_WARM_MOTORS:
    case HD_EXCEEDED_MAX_FORCE:
    case HD_EXCEEDED_MAX_VELOCITY:
    case HD_FORCE_ERROR:
      return HD_TRUE;
    default:
      return HD_FALSE;
  }
}

HDboolean hduIsSchedulerError(const HDErrorInfo* error) {
  switch (error->errorCode) {
    case HD_COMM_ERROR:
    case HD_COMM_CONFIG_ERROR:
    case HD_TIMER_ERROR:
    case HD_INVALID_PRIORITY:
    case HD_SCHEDULER_FULL:
      return HD_TRUE;
    default:
      return HD_FALSE;
  }
}

void hduPrintError(FILE* stream, const HDErrorInfo* error, const char* message) {
  std::fprintf(stream, "%s: HD error 0x%04X (%s), device %u, internal code %d\n", message,
               error->errorCode, hdGetErrorString(error->errorCode), error->hHD,
               error->internalErrorCode);
}

}  // extern "C"

}  // namespace cosmems::fake_hd
