/* Umbrella header of the HD API as implemented by the project's fake (cosmems_fake_hd): the
 * names, types, signatures and numeric values of OpenHaptics' HD API, so that a backend written
 * for the SDK compiles and runs unchanged against it. */
#ifndef COSMEMS_FAKE_HD_H
#define COSMEMS_FAKE_HD_H

#include "HD/hdDefines.h"
#include "HD/hdDevice.h"
#include "HD/hdExport.h"
#include "HD/hdScheduler.h"

#endif
