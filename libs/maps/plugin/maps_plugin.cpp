/* hslam: MRPT plug-in module registering hslam::maps::CTiledOccupancyGridMap2D
 * (map factory alias "tiledOccupancyGrid" and the serializable class) at load
 * time, for MRPT apps that load plug-ins (-p / --plugins of rawlog-edit and
 * rawlog-grabber) or through LD_PRELOAD for the others (icp-slam, rbpf-slam,
 * observations2map...); see ../shared/notes/mrpt-plugins-and-protocols.md 1.1-1.3. */
#include <hslam/maps/CTiledOccupancyGridMap2D.h>
#include <mrpt/core/initializer.h>

MRPT_INITIALIZER(hslam_maps_plugin_register) { hslam::maps::registerTiledMapClasses(); }
