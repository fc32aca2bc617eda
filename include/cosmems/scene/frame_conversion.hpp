#pragma once

#include <vector>

#include "cosmems/analysis/comb_drive.hpp"
#include "cosmems/analysis/frame_load_case.hpp"
#include "cosmems/analysis/frame_pullin_options.hpp"
#include "cosmems/analysis/frame_record_point.hpp"
#include "cosmems/scene/scene.hpp"
#include "cosmems/structure/frame_model.hpp"
#include "cosmems/structure/straight_beam.hpp"
#include "cosmems/structure/structure_description.hpp"
#include "cosmems/time/voltage_drive.hpp"

namespace cosmems {

// From a validated device scene (IsDevice(structure.kind)) to the core's netlist, in SI.

/// A frame's nodes, beams and bodies with their names resolved to indices (each beam's
/// thickness, element count and material default to structure.thickness, model.elements and
/// [material]; a body's density is its material's), or the netlist a generator makes of its
/// design parameters: a parametric device's, or a cantilever's or a bridge's one member
/// (StraightBeam: nodes "root" and "tip", planar with model.dimension = 2, with its residual
/// axial load). Validated (StructureDescription::Validate).
StructureDescription MakeStructureDescription(const Scene& scene);

/// Whether the scene is a cantilever or a bridge: StraightBeam's one member, whose fields a
/// report lists along its axis (x) and which buckles under an axial compression of its ends.
bool IsStraightBeam(const Scene& scene);

/// The couplings the scene's theory adds to the frame's linear members: a device with
/// model.theory = "stretching" stretches every member as it bends.
FrameCouplings MakeFrameCouplings(const Scene& scene);

/// The scene's [[loads.points]] at their nodes or bodies, a beam's tip loads at its node "tip" and
/// its midspan force halfway along its member, and loads.distributed on every member.
FrameLoadCase MakeFrameLoadCase(const Scene& scene, const StructureDescription& structure);

/// The scene's [[effects.combs]] on their bodies, each as thick as its body, with its
/// alternating voltage.
std::vector<CombDrive> MakeCombDrives(const Scene& scene, const StructureDescription& structure);

/// The scene's electrodes under a device (structure.gap; effects.electrostatic's electrodes, or
/// one under all of it, and fringing) and a pull-in's voltage bound (analysis.voltage_max).
FramePullInOptions MakeFramePullInOptions(const Scene& scene);

/// The electrodes' voltage in a device's transient: effects.electrostatic's voltage, plus its
/// ac_voltage at its frequency.
VoltageDrive MakeElectrodeDrive(const Scene& scene);

/// The points a transient records: a cantilever's tip, a bridge's midspan; a device's the nodes
/// and bodies of analysis.record (a name that is a node and a body is the node), then every
/// other body's centre. The first is watched.
std::vector<FrameRecordPoint> MakeFrameRecord(const Scene& scene,
                                              const StructureDescription& structure);

}  // namespace cosmems
