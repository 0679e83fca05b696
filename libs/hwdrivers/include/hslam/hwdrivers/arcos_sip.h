/* hslam: ARCOS standard server information packet (SIP, types 0x32/0x33).
 *
 * Layout after the type byte, little-endian (AriaCoda ArRobot::processMotorPacket,
 * p2os SIP::ParseStandard, see ../shared/notes/mrpt-plugins-and-protocols.md s.3):
 *   XPOS u16 (15 bits used), YPOS u16, THPOS i16 (2*pi/4096 rad), LVEL i16, RVEL i16 (mm/s),
 *   BATTERY u8 (0.1 V), STALL+BUMP u16, CONTROL i16, FLAGS u16, COMPASS u8,
 *   SONAR_COUNT u8, SONAR_COUNT x (index u8, range u16 mm),
 *   GRIP u8, ANPORT u8, ANALOG u8, DIGIN u8, DIGOUT u8, BATTERYX10 u16,
 *   CHARGESTATE u8, ROTVEL i16 (0.1 deg/s), FAULTFLAGS u16, then optional newer fields
 *   (ignored). The tail after the sonar block is optional (older firmware). */
#pragma once

#include <cstdint>
#include <optional>
#include <vector>

namespace hslam::hwdrivers::arcos
{
struct TSonarReading
{
	uint8_t index = 0;
	uint16_t range_raw = 0;  //!< robot range units (mm on a P3-DX, RangeConvFactor 1)
};

struct TSip
{
	uint8_t type = 0x32;
	uint16_t xpos_raw = 0, ypos_raw = 0;  //!< 15-bit wrapping position counters
	int16_t thpos_raw = 0;  //!< heading, angular units
	int16_t vel_left_raw = 0, vel_right_raw = 0;  //!< wheel speeds, velocity units (mm/s)
	uint8_t battery_dV = 0;  //!< volts x 10
	uint16_t stall_bump = 0;
	int16_t control = 0;
	uint16_t flags = 0;
	uint8_t compass = 0;
	std::vector<TSonarReading> sonars;
	bool has_tail = false;  //!< the fields below were present
	uint8_t grip = 0, anport = 0, analog = 0, digin = 0, digout = 0;
	uint16_t battery_x10 = 0;
	uint8_t charge_state = 0;
	int16_t rotvel_x10 = 0;  //!< rotational velocity, 0.1 deg/s
	uint16_t fault_flags = 0;

	bool motorsEnabled() const { return flags & 0x0001; }
	bool leftStall() const { return stall_bump & 0x0001; }
	bool rightStall() const { return stall_bump & 0x0100; }
	uint8_t rearBumpers() const { return (stall_bump >> 1) & 0x7F; }
	uint8_t frontBumpers() const { return (stall_bump >> 9) & 0x7F; }
	/** Battery voltage, preferring the 0.1 V-resolution tail field. */
	double batteryVolts() const { return (has_tail && battery_x10 > 0) ? battery_x10 / 10.0 : battery_dV / 10.0; }
};

/** Decodes a SIP payload (type byte first); nullopt if it is not a standard
 * SIP or too short for its declared sonar count. */
std::optional<TSip> decodeSip(const uint8_t* payload, size_t n);
inline std::optional<TSip> decodeSip(const std::vector<uint8_t>& p) { return decodeSip(p.data(), p.size()); }

/** Encodes a SIP payload (for emulators and tests); the tail is written if has_tail. */
std::vector<uint8_t> encodeSip(const TSip& sip);

}  // namespace hslam::hwdrivers::arcos
