#pragma once
/// \file
/// \brief The rviz scene around the cable's line: the cable as per-link cylinders of its real diameter
///        coloured by tension, the vessel (hull, deckhouse, A-frame) and the ROV (body, thrusters) as
///        simple marker compositions in their own TF frames. Prepared once, then only filled.
///
/// The seabed is drawn apart (seabed_markers.h): its own latched marker, published once, and the links
/// lying on it, so this scene's fixed marker count does not depend on it.

#include <string>
#include <vector>

#include <Eigen/Core>
#include <visualization_msgs/Marker.h>

#include "cable_dynamics/params/cable_params.h"
#include "cable_dynamics/ros/output_source.h"

namespace cable_dynamics {

/// Sizes of the two bodies' shapes (`ros.vessel_size`, `ros.rov_size`); drawing only, no physics.
struct BodyShapes {
  Eigen::Vector3d vessel_size{30.0, 8.0, 4.0};  ///< hull length, beam, depth (keel to deck) [m]
  Eigen::Vector3d rov_size{2.0, 1.4, 1.2};      ///< body length, width, height [m]
};

/// Markers of the vessel (3) and the ROV (5): vessel_hull, vessel_deckhouse, vessel_aframe (LINE_LIST),
/// rov_body, rov_thrusters (ids 0..3, CYLINDER). Constant in the bodies' frames `vessel_frame` and
/// `rov_frame`. The vessel's origin is on its waterline (the hull 40 % below, 60 % above it); the A-frame's
/// feet stand on the deck at the stern and its top is the hang-off point (params.base.hang_off), so the
/// cable leaves the A-frame's sheave.
constexpr int kSceneMarkerCount = 8;
void prepareBodyMarkers(const CableParams& params, const BodyShapes& shapes, const std::string& vessel_frame,
                        const std::string& rov_frame, visualization_msgs::Marker* markers);

/// The cable as one CYLINDER per slot (ns cable_tube, id = slot), in `paper_frame`: diameter the link's
/// section's (scale.x = scale.y), length and pose from the link's ends, each cycle (fillTubeMarkers).
void prepareTubeMarkers(const CableParams& params, const std::string& paper_frame,
                        visualization_msgs::Marker* markers);
/// How rviz colours the cable (`ros.markers.colour_by`): by tension against the tension scale, or by
/// utilisation against the limits (blue 0, green 0.5, red at 1 = a limit and above).
enum class MarkerColour { kTension, kUtilisation };

/// Places each deployed link's cylinder between its ends, coloured by its tension against `tension_scale`
/// [N]; a slot on the winch's drum gets action DELETE (nothing left in rviz). `markers` holds one per slot.
/// With `by_utilisation` each link is coloured by its utilisation instead (utilisationColor).
void fillTubeMarkers(const OutputSource& source, double tension_scale, visualization_msgs::Marker* markers,
                     bool by_utilisation = false);

/// Blue (slack) through green to red (the top of the scale); compression in grey.
std_msgs::ColorRGBA tensionColor(double tension, double scale);
/// A utilisation's colour [-]: the tension's scale with its top at 1, a limit (blue 0, green 0.5, red at
/// and above 1).
inline std_msgs::ColorRGBA utilisationColor(double utilisation) { return tensionColor(utilisation, 1.0); }

}  // namespace cable_dynamics
