/* Tests of SIP decoding (hand-built bytes, negative velocities, bumpers) and of
 * the odometry's wrap-around handling. */
#include <gtest/gtest.h>
#include <hslam/hwdrivers/CArcosOdometry.h>
#include <hslam/hwdrivers/arcos_protocol.h>
#include <hslam/hwdrivers/arcos_sip.h>

using namespace hslam::hwdrivers;
using namespace hslam::hwdrivers::arcos;
using Bytes = std::vector<uint8_t>;

namespace
{
/** A SIP written byte by byte from the field table (notes s.3). */
Bytes handBuiltSip(bool withTail)
{
	Bytes b{0x33,  // type: moving
			0xF0, 0x7F,  // XPOS 0x7FF0 = 32752
			0x10, 0x00,  // YPOS 16
			0x9C, 0xFF,  // THPOS -100
			0x6A, 0xFF,  // LVEL -150 mm/s
			0xFA, 0x00,  // RVEL 250 mm/s
			0x7D,  // BATTERY 12.5 V
			0x01, 0x02,  // STALL+BUMP 0x0201: left stall + front bumper 1
			0x00, 0x00,  // CONTROL
			0x01, 0x00,  // FLAGS: motors on
			0x00,  // COMPASS
			0x02,  // SONAR_COUNT
			0x03, 0xD2, 0x04,  // sonar 3: 1234 mm
			0x04, 0x88, 0x13};  // sonar 4: 5000 mm
	if (withTail)
		for (uint8_t x : {0, 0, 0, 0, 0,  // grip, anport, analog, digin, digout
						  0x7E, 0x00,  // BATTERYX10 12.6 V
						  0x00,  // CHARGESTATE
						  0x1B, 0xFF,  // ROTVEL -229 = -22.9 deg/s
						  0x00, 0x00})  // FAULTFLAGS
			b.push_back(x);
	return b;
}

TSip sipAt(int x, int y, int th)
{
	TSip s;
	s.xpos_raw = static_cast<uint16_t>(x & 0x7FFF);
	s.ypos_raw = static_cast<uint16_t>(y & 0x7FFF);
	s.thpos_raw = static_cast<int16_t>(th);
	return s;
}
}  // namespace

TEST(ArcosSip, DecodesHandBuiltPacket)
{
	const auto s = decodeSip(handBuiltSip(true));
	ASSERT_TRUE(s);
	EXPECT_EQ(s->type, 0x33);
	EXPECT_EQ(s->xpos_raw, 32752);
	EXPECT_EQ(s->ypos_raw, 16);
	EXPECT_EQ(s->thpos_raw, -100);
	EXPECT_EQ(s->vel_left_raw, -150);
	EXPECT_EQ(s->vel_right_raw, 250);
	EXPECT_TRUE(s->leftStall());
	EXPECT_FALSE(s->rightStall());
	EXPECT_EQ(s->frontBumpers(), 1);
	EXPECT_EQ(s->rearBumpers(), 0);
	EXPECT_TRUE(s->motorsEnabled());
	ASSERT_EQ(s->sonars.size(), 2u);
	EXPECT_EQ(s->sonars[0].index, 3);
	EXPECT_EQ(s->sonars[0].range_raw, 1234);
	EXPECT_EQ(s->sonars[1].range_raw, 5000);
	EXPECT_TRUE(s->has_tail);
	EXPECT_EQ(s->rotvel_x10, -229);
	EXPECT_DOUBLE_EQ(s->batteryVolts(), 12.6);
	// Round trip through the encoder gives the same bytes.
	EXPECT_EQ(encodeSip(*s), handBuiltSip(true));
}

TEST(ArcosSip, OlderFirmwareWithoutTailAndMalformedPackets)
{
	const auto s = decodeSip(handBuiltSip(false));
	ASSERT_TRUE(s);
	EXPECT_FALSE(s->has_tail);
	EXPECT_DOUBLE_EQ(s->batteryVolts(), 12.5);
	Bytes cut = handBuiltSip(false);
	cut.resize(cut.size() - 1);  // last sonar reading incomplete
	EXPECT_FALSE(decodeSip(cut));
	Bytes notSip = handBuiltSip(false);
	notSip[0] = 0x20;  // CONFIG packet type
	EXPECT_FALSE(decodeSip(notSip));
	EXPECT_FALSE(decodeSip(Bytes{0x32}));
}

TEST(ArcosOdometry, VelocitiesFromWheelsAndRotvel)
{
	CArcosOdometry odo;
	odo.update(*decodeSip(handBuiltSip(true)));
	EXPECT_NEAR(odo.velocityLocal().vx, 0.050, 1e-12);  // (-150 + 250)/2 mm/s
	EXPECT_NEAR(odo.velocityLocal().omega, -22.9 * M_PI / 180, 1e-12);  // ROTVEL field
	EXPECT_NEAR(odo.leftWheel_mps(), -0.150, 1e-12);
	CArcosOdometry old;
	old.update(*decodeSip(handBuiltSip(false)));
	EXPECT_NEAR(old.velocityLocal().omega, 0.5 * 400 * 0.0056, 1e-12);  // (vr - vl)/2 * DiffConv
	// Initial pose = the SIP's own counters, read as signed 15-bit values.
	EXPECT_NEAR(odo.pose().x(), -0.016, 1e-9);
	EXPECT_NEAR(odo.pose().phi(), -100 * 0.001534, 1e-9);
}

TEST(ArcosOdometry, PositionCountersWrapAround)
{
	EXPECT_EQ(CArcosOdometry::unwrapDelta15(68, 32700), 136);
	EXPECT_EQ(CArcosOdometry::unwrapDelta15(32700, 68), -136);
	EXPECT_EQ(CArcosOdometry::unwrapDelta15(500, 400), 100);

	CArcosOdometry odo;
	odo.update(sipAt(16300, 0, 0));  // first SIP without SETO: signed 15-bit
	EXPECT_NEAR(odo.pose().x(), 16.3, 1e-9);
	odo.reset();
	odo.update(sipAt(-16300, 0, 0));
	EXPECT_NEAR(odo.pose().x(), -16.3, 1e-9);
	odo.resetToOrigin();
	int x = 0;
	// Drive 70 m forward in 100 mm steps: the counter wraps twice, no jump.
	for (int k = 0; k < 700; ++k) odo.update(sipAt(x += 100, 0, 0));
	EXPECT_NEAR(odo.pose().x(), 70.0, 1e-6);
	// Backwards from the origin: 0 -> -20 mm is raw 32748.
	odo.resetToOrigin();
	odo.update(sipAt(-20, 0, 0));
	EXPECT_NEAR(odo.pose().x(), -0.020, 1e-9);
	odo.update(sipAt(-20 + 136, 0, 0));
	EXPECT_NEAR(odo.pose().x(), 0.116, 1e-9);
	// Negative y: 0 -> -1 mm is raw 32767.
	odo.update(sipAt(-20 + 136, -1, 0));
	EXPECT_NEAR(odo.pose().y(), -0.001, 1e-9);
}

TEST(ArcosOdometry, HeadingWrapsAtPlusMinusPi)
{
	CArcosOdometry odo;
	odo.update(sipAt(0, 0, 2040));
	odo.update(sipAt(0, 0, -2040));  // +16 units across +pi
	const double expected = mrpt::math::wrapToPi((2040 + 16) * 0.001534);
	EXPECT_NEAR(odo.pose().phi(), expected, 1e-9);
	EXPECT_LT(odo.pose().phi(), 0);  // just past +pi is near -pi
	odo.update(sipAt(0, 0, 2040));  // back
	EXPECT_NEAR(odo.pose().phi(), 2040 * 0.001534, 1e-9);
}
