/* Test hooks of the fake HD API (cosmems_fake_hd only; the SDK has no such header). They set
 * what the simulated device reports, drive its scheduler tick by tick, inject failures and read
 * back what the device was told to do.
 *
 * Ticks are numbered from 0 since the last hdFakeReset(); the scheduler thread (or hdFakeStep)
 * runs tick k at device time k / rate seconds. Hooks that change the device take effect at the
 * next tick. */
#ifndef COSMEMS_FAKE_HD_FAKE_H
#define COSMEMS_FAKE_HD_FAKE_H

#include "HD/hdDefines.h"
#include "HD/hdScheduler.h"

#ifdef __cplusplus
extern "C" {
#endif

/* What the simulated device reports, in the HD API's units. */
typedef struct {
  char model[64];                  /* HD_DEVICE_MODEL_TYPE */
  char vendor[64];                 /* HD_DEVICE_VENDOR */
  HDdouble max_force_n;            /* HD_NOMINAL_MAX_FORCE; also the clamping limit */
  HDdouble max_continuous_force_n; /* HD_NOMINAL_MAX_CONTINUOUS_FORCE */
  HDdouble max_stiffness_n_per_mm; /* HD_NOMINAL_MAX_STIFFNESS */
  HDdouble max_damping_ns_per_mm;  /* HD_NOMINAL_MAX_DAMPING */
  HDdouble usable_workspace_mm[6]; /* HD_USABLE_WORKSPACE_DIMENSIONS: min x y z, max x y z */
  HDdouble max_workspace_mm[6];    /* HD_MAX_WORKSPACE_DIMENSIONS, same order */
  HDdouble tabletop_offset_mm;     /* HD_TABLETOP_OFFSET */
  HDint input_dof;                 /* HD_INPUT_DOF */
  HDint output_dof;                /* HD_OUTPUT_DOF */
  HDint calibration_styles;        /* HD_CALIBRATION_STYLE bitmask */
} HDFakeSpecs;

/* Gives the stylus tip position [mm] at device time `time_s`. Called on the ticking thread with
 * the fake's lock held: it must not call the HD API. */
typedef void (*HDFakeMotion)(HDdouble time_s, HDdouble position_mm[3], void* user);

/* Back to the power-on state: scheduler stopped (its thread joined), no device initialised, no
 * operations, empty error stack and logs, default specs (hdFakeDefaultSpecs), stylus fixed at
 * the origin, calibration OK, threaded scheduler, nothing injected. Call it between tests. */
void hdFakeReset(void);

/* The PHANTOM Omni's datasheet figures: 3.3 N peak, 0.88 N continuous, 0.7 N/mm and
 * 0.005 N s/mm (the closed-loop values renderable at 1 kHz), usable box +-80 x +-60 x +-35 mm,
 * inkwell calibration, 6 sensed and 3 actuated degrees of freedom. */
void hdFakeDefaultSpecs(HDFakeSpecs* specs);
void hdFakeSetSpecs(const HDFakeSpecs* specs);

/* Manual ticks (set before hdStartScheduler): no scheduler thread; hdFakeStep runs the ticks
 * on the caller's thread, and hdScheduleSynchronous runs its callback inline (nothing else
 * could run it). Update rates then read as the nominal rate. */
void hdFakeSetManualTicks(HDboolean manual);
/* Runs `count` ticks now; only while the scheduler is started in manual mode. Returns the
 * number of ticks run. */
HDulong hdFakeStep(HDulong count);
/* Ticks run since the last reset. */
HDulong hdFakeTickCount(void);

/* Stylus motion: a trajectory, or (hdFakeSetPosition) a fixed position. Velocity is the
 * difference of two ticks' positions times the rate, as a driver estimates it. */
void hdFakeSetMotion(HDFakeMotion motion, void* user);
void hdFakeSetPosition(const HDdouble position_mm[3]);
void hdFakeSetButtons(HDint buttons);

/* What hdCheckCalibration reports. hdUpdateCalibration turns NEEDS_UPDATE into OK;
 * NEEDS_MANUAL_INPUT stays until this hook changes it (the user has to act). */
void hdFakeSetCalibration(HDenum status);

/* Raises `code` at tick `tick`: at that tick's outer hdEndFrame, or at the tick's end when no
 * frame ended. A force error (HD_WARM_MOTORS, ...) refuses the frame's force: the device outputs
 * zero. A scheduler error (HD_COMM_ERROR, HD_TIMER_ERROR, ...) loses the frame's command: the
 * motors keep the force they had until force output is disabled or the scheduler stops. Either
 * leaves the scheduler running; the caller decides what a scheduler error means. */
void hdFakeInjectError(HDerror code, HDulong tick);
/* The next `count` hdInitDevice calls fail with `code` (e.g. HD_DEVICE_ALREADY_INITIATED). */
void hdFakeFailInit(HDerror code, HDint count);
/* Without a device, every hdInitDevice fails with HD_DEVICE_FAULT, as when none answers. */
void hdFakeSetDevicePresent(HDboolean present);

/* The force the device outputs now [N], latched at the last outer hdEndFrame; zero from the
 * moment force output is disabled. */
void hdFakeLatchedForce(HDdouble force_n[3]);
/* The force output during each tick of the first 65536 ticks since the reset [N]. */
HDulong hdFakeForceLogSize(void);
void hdFakeForceLogEntry(HDulong tick, HDdouble force_n[3]);

/* Set-up and shutdown calls in the order they were made (function names without arguments):
 * hdInitDevice, hdDisableDevice, hdMakeCurrentDevice, hdEnable, hdDisable, hdSetSchedulerRate,
 * hdScheduleAsynchronous, hdUnschedule, hdStartScheduler, hdStopScheduler, hdCheckCalibration,
 * hdUpdateCalibration. Per-tick calls are not recorded. hdFakeCall returns NULL past the end. */
HDulong hdFakeCallCount(void);
HDstring hdFakeCall(HDulong index);

#ifdef __cplusplus
}
#endif

#endif
