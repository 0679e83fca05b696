/* hslam: MRPT plug-in module for rawlog-grabber / rawlog-edit (-p <this .so>).
 *
 * MRPT's loader (mrpt::system::loadPluginModule) only dlopen()s the module;
 * registration must happen in a load-time constructor. DEFINE_/IMPLEMENTS_
 * GENERIC_SENSOR do not register by themselves (see
 * ../shared/notes/mrpt-plugins-and-protocols.md s.1.3(a)). */
#include <hslam/hwdrivers/CPioneerSensor.h>
#include <mrpt/core/initializer.h>

MRPT_INITIALIZER(hslam_hwdrivers_plugin_register) { hslam::hwdrivers::registerHwdriversSensors(); }
