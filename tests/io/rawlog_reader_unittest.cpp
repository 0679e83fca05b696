/* CRawlogReader against crafted and damaged rawlogs (issue 15, items 1 and
 * 6): absurd declared sizes are refused before MRPT allocates, a damaged
 * object is skipped by resynchronising on the next object header (the bytes
 * skipped are exactly the damaged object), and a cut file still ends with a
 * "truncated" error after everything before the cut. The rawlogs are written
 * here by MRPT's own serialisation, in both formats, plain and gz. */
#include <gtest/gtest.h>

#include <algorithm>
#include <hslam/io/CRawlogReader.h>
#include <hslam/io/rawlog_declared_sizes.h>
#include <hslam/testing/temp_dir.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationRange.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/archiveFrom_std_vector.h>
#include <sys/resource.h>

#include <cstring>
#include <fstream>

using namespace hslam::io;

namespace
{
using TBytes = std::vector<uint8_t>;

TBytes serialize(const mrpt::serialization::CSerializable& o)
{
	TBytes v;
	auto a = mrpt::serialization::archiveFrom(v);
	a.WriteObject(&o);
	return v;
}

mrpt::obs::CObservation2DRangeScan::Ptr makeScan(int k)
{
	auto s = std::make_shared<mrpt::obs::CObservation2DRangeScan>();
	s->sensorLabel = "LASER";
	s->aperture = static_cast<float>(M_PI);
	s->maxRange = 8.0f;
	s->resizeScan(181);
	for (size_t i = 0; i < 181; ++i)
	{
		s->setScanRange(i, 1.0f + 0.01f * static_cast<float>(k));
		s->setScanRangeValidity(i, true);
	}
	s->timestamp = mrpt::Clock::fromDouble(1000.0 + k);
	return s;
}

/** The serialised objects of an observations-only rawlog of n scans. */
std::vector<TBytes> scanObjects(int n)
{
	std::vector<TBytes> objs;
	for (int k = 0; k < n; ++k) objs.push_back(serialize(*makeScan(k)));
	return objs;
}

void writeFile(const std::string& path, const std::vector<TBytes>& objs, bool gz)
{
	TBytes all;
	for (const auto& o : objs) all.insert(all.end(), o.begin(), o.end());
	if (gz)
	{
		mrpt::io::CFileGZOutputStream f(path);
		f.Write(all.data(), all.size());
	}
	else
		std::ofstream(path, std::ios::binary).write(reinterpret_cast<const char*>(all.data()), static_cast<std::streamsize>(all.size()));
}

void putU32(TBytes& b, size_t at, uint32_t v) { std::memcpy(b.data() + at, &v, 4); }

/** Offset of the beam count in a serialised MRPT 2.5 scan (v7), found in the
 * bytes themselves: the first u32 equal to the scan size after the pose. */
size_t beamCountOffset(const TBytes& scan)
{
	for (size_t i = 40; i + 4 <= scan.size(); ++i)
	{
		uint32_t v;
		std::memcpy(&v, scan.data() + i, 4);
		if (v == 181u) return i;
	}
	return 0;
}

struct TReadResult
{
	std::vector<double> stamps;  //!< of the scans read
	std::vector<TRawlogProblem> problems;
	std::string error;
};

TReadResult readAll(const std::string& path)
{
	TReadResult r;
	CRawlogReader reader(path);
	TRawlogEntry e;
	try
	{
		while (reader.next(e))
		{
			if (e.observation) r.stamps.push_back(mrpt::Clock::toDouble(e.observation->timestamp));
			if (e.frame)
				for (const auto& o : *e.frame) r.stamps.push_back(mrpt::Clock::toDouble(o->timestamp));
		}
	}
	catch (const rawlog_error& ex)
	{
		r.error = ex.what();
	}
	r.problems = reader.problems();
	return r;
}

long peakRss_kB()
{
	rusage u{};
	getrusage(RUSAGE_SELF, &u);
	return u.ru_maxrss;
}
}  // namespace

TEST(RawlogReader, TheScanLayoutIsTheOneTheChecksKnow)
{
	const TBytes scan = serialize(*makeScan(0));
	EXPECT_EQ(beamCountOffset(scan), 164u);  // header 35, version, 9 bytes, CPose3D 119
	const auto ok = checkDeclaredSizes(scan.data(), scan.size(), true);
	EXPECT_EQ(ok.result, TDeclaredSizeCheck::EResult::Plausible);
	TBytes bad = scan;
	putU32(bad, 164, 0x7fffffffu);
	const auto r = checkDeclaredSizes(bad.data(), bad.size(), false);
	EXPECT_EQ(r.result, TDeclaredSizeCheck::EResult::Absurd);
	EXPECT_NE(r.message.find("beam count 2147483647"), std::string::npos) << r.message;
}

TEST(RawlogReader, AbsurdBeamCountsAreRefusedBeforeMrptAllocates)
{
	for (bool gz : {false, true})
	{
		hslam::testing::CTempDir tmp;
		auto objs = scanObjects(10);
		putU32(objs[3], beamCountOffset(objs[3]), 0x7fffffffu);  // 2^31 beams: 19 GB in MRPT
		putU32(objs[6], beamCountOffset(objs[6]), 0xffffffffu);
		writeFile(tmp.file("crafted.rawlog"), objs, gz);
		const long rssBefore_kB = peakRss_kB();
		const auto r = readAll(tmp.file("crafted.rawlog"));
		EXPECT_EQ(r.error, "");
		// The 8 good scans, in order; the two crafted ones refused and reported.
		ASSERT_EQ(r.stamps.size(), 8u);
		EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1001, 1002, 1004, 1005, 1007, 1008, 1009}));
		ASSERT_EQ(r.problems.size(), 2u);
		EXPECT_EQ(r.problems[0].entry, 3u);
		EXPECT_NE(r.problems[0].message.find("crafted.rawlog: entry 3"), std::string::npos) << r.problems[0].message;
		EXPECT_NE(r.problems[0].message.find("beam count 2147483647"), std::string::npos) << r.problems[0].message;
		EXPECT_NE(r.problems[1].message.find("beam count 4294967295"), std::string::npos) << r.problems[1].message;
		// Exactly the crafted objects were skipped.
		EXPECT_EQ(r.problems[0].skipped_bytes, objs[3].size());
		EXPECT_EQ(r.problems[1].skipped_bytes, objs[6].size());
		// Nothing near the 8-16 GB MRPT would have asked for.
		EXPECT_LT(peakRss_kB() - rssBefore_kB, 200 * 1024);
	}
}

TEST(RawlogReader, AbsurdSizesInsideASensoryFrameAreRefused)
{
	hslam::testing::CTempDir tmp;
	std::vector<TBytes> objs;
	for (int k = 0; k < 6; ++k)
	{
		mrpt::obs::CActionCollection acts;
		mrpt::obs::CActionRobotMovement2D move;
		acts.insert(move);
		mrpt::obs::CSensoryFrame sf;
		sf.insert(makeScan(k));
		objs.push_back(serialize(acts));
		TBytes frame = serialize(sf);
		if (k == 2)
		{  // the nested scan's beam count: find the scan's own bytes inside the frame
			const TBytes scan = serialize(*makeScan(k));
			const auto at = std::search(frame.begin(), frame.end(), scan.begin(), scan.end());
			ASSERT_NE(at, frame.end());
			putU32(frame, static_cast<size_t>(at - frame.begin()) + beamCountOffset(scan), 0x7fffffffu);
		}
		objs.push_back(frame);
	}
	writeFile(tmp.file("sf.rawlog.gz"), objs, true);
	const long rssBefore_kB = peakRss_kB();
	const auto r = readAll(tmp.file("sf.rawlog.gz"));
	EXPECT_EQ(r.error, "");
	EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1001, 1003, 1004, 1005}));
	ASSERT_EQ(r.problems.size(), 1u);
	// The frame is read from its own bounded buffer: MRPT's parse of the nested
	// scan fails inside it (reported as corrupt data of that entry) instead of
	// allocating 8 GB for 2^31 beams.
	EXPECT_NE(r.problems[0].message.find("sf.rawlog.gz: entry 2"), std::string::npos) << r.problems[0].message;
	EXPECT_LT(peakRss_kB() - rssBefore_kB, 200 * 1024);
}

TEST(RawlogReader, AbsurdLabelAndCommentLengthsAreRefused)
{
	hslam::testing::CTempDir tmp;
	auto objs = scanObjects(4);
	const size_t labelAt = beamCountOffset(objs[1]) + 4 + 5 * 181 + 4 + 8 + 4;
	ASSERT_EQ(objs[1][labelAt], 5u);  // "LASER"
	putU32(objs[1], labelAt, 0xfffffff0u);
	mrpt::obs::CObservationComment c;
	c.text = "a comment";
	TBytes comment = serialize(c);
	putU32(comment, 1 + 30 + 1, 0x7ffffff0u);
	objs.insert(objs.begin() + 3, comment);
	writeFile(tmp.file("labels.rawlog"), objs, false);
	const auto r = readAll(tmp.file("labels.rawlog"));
	EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1002, 1003}));
	ASSERT_EQ(r.problems.size(), 2u);
	EXPECT_NE(r.problems[0].message.find("sensor label length"), std::string::npos) << r.problems[0].message;
	EXPECT_NE(r.problems[1].message.find("comment length"), std::string::npos) << r.problems[1].message;
}

TEST(RawlogReader, ABitFlipLosesOneEntryNotTheRest)
{
	for (bool gz : {false, true})
	{
		hslam::testing::CTempDir tmp;
		auto objs = scanObjects(20);
		objs[9].back() ^= 0x01;  // the end-of-object flag of scan 9
		objs[14][40] ^= 0x10;  // inside scan 14's header fields: a bit of rightToLeft/maxRange
		objs[14][objs[14].size() - 1] = 0x00;
		writeFile(tmp.file("flipped.rawlog"), objs, gz);
		const auto r = readAll(tmp.file("flipped.rawlog"));
		EXPECT_EQ(r.error, "");
		ASSERT_EQ(r.stamps.size(), 18u);
		EXPECT_EQ(r.stamps[8], 1008.0);
		EXPECT_EQ(r.stamps[9], 1010.0);
		EXPECT_EQ(r.stamps.back(), 1019.0);
		ASSERT_EQ(r.problems.size(), 2u);
		EXPECT_EQ(r.problems[0].entry, 9u);
		EXPECT_EQ(r.problems[0].skipped_bytes, objs[9].size());
		EXPECT_EQ(r.problems[1].skipped_bytes, objs[14].size());
		EXPECT_NE(r.problems[0].message.find("flipped.rawlog: entry 9: corrupt data"), std::string::npos) << r.problems[0].message;
	}
}

TEST(RawlogReader, TruncatedFileKeepsWhatWasReadAndSaysTruncated)
{
	hslam::testing::CTempDir tmp;
	auto objs = scanObjects(10);
	objs[7].resize(objs[7].size() / 2);
	objs.resize(8);
	writeFile(tmp.file("cut.rawlog.gz"), objs, true);
	const auto r = readAll(tmp.file("cut.rawlog.gz"));
	EXPECT_EQ(r.stamps.size(), 7u);
	EXPECT_NE(r.error.find("cut.rawlog.gz: entry 7: file is truncated"), std::string::npos) << r.error;
	EXPECT_TRUE(r.problems.empty());
}

TEST(RawlogReader, GarbageWithNoObjectAfterItIsAnError)
{
	hslam::testing::CTempDir tmp;
	auto objs = scanObjects(3);
	objs.push_back(TBytes(300, 0xA5));
	writeFile(tmp.file("tail.rawlog"), objs, false);
	const auto r = readAll(tmp.file("tail.rawlog"));
	EXPECT_EQ(r.stamps.size(), 3u);
	EXPECT_NE(r.error.find("tail.rawlog: entry 3: corrupt data"), std::string::npos) << r.error;
	EXPECT_NE(r.error.find("no readable object after byte"), std::string::npos) << r.error;
}

TEST(RawlogReader, AbsurdSonarCountsAreRefusedInEveryRangeVersion)
{
	// MRPT 2.5 reads CObservationRange versions 0-3 alike up to the sensor
	// count and resizes before reading the sensors; a fuzzer found a version-0
	// object asking for 2 GB (tests/fuzz/regressions/rawlog_reader). Each
	// version with a crafted count is refused, the scans around it are kept.
	for (uint8_t version = 0; version <= 3; ++version)
	{
		hslam::testing::CTempDir tmp;
		mrpt::obs::CObservationRange sonar;
		sonar.sensorLabel = "SONAR";
		sonar.sensedData.resize(8);
		TBytes bytes = serialize(sonar);
		const size_t versionAt = 1 + std::strlen("mrpt::obs::CObservationRange");
		ASSERT_EQ(bytes[versionAt], 3u);  // MRPT 2.5 writes version 3
		bytes[versionAt] = version;
		putU32(bytes, versionAt + 1 + 12, 0x10000000u);  // 2^28 sensors
		auto objs = scanObjects(3);
		objs.insert(objs.begin() + 1, bytes);
		writeFile(tmp.file("sonar.rawlog"), objs, false);
		const long rssBefore_kB = peakRss_kB();
		const auto r = readAll(tmp.file("sonar.rawlog"));
		EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1001, 1002})) << "version " << int(version);
		ASSERT_EQ(r.problems.size(), 1u) << "version " << int(version);
		EXPECT_NE(r.problems[0].message.find("range sensor count 268435456"), std::string::npos) << r.problems[0].message;
		EXPECT_LT(peakRss_kB() - rssBefore_kB, 200 * 1024);
	}
}

TEST(RawlogReader, ADamagedNamespaceDoesNotEscapeTheSizeChecks)
{
	// MRPT resolves a stored class name by the part after the last "::", so
	// "mrpt::ocs::CObservation2DRangeScan" still reads as a scan; the checks
	// must see it as one too (a fuzzer made MRPT allocate 1 GB this way).
	hslam::testing::CTempDir tmp;
	auto objs = scanObjects(4);
	ASSERT_EQ(std::memcmp(objs[2].data() + 1, "mrpt::obs::", 11), 0);
	objs[2][7] = 'c';  // mrpt::obs:: -> mrpt::ocs::
	putU32(objs[2], beamCountOffset(objs[2]), 0x7fffffffu);
	writeFile(tmp.file("ns.rawlog"), objs, false);
	const long rssBefore_kB = peakRss_kB();
	const auto r = readAll(tmp.file("ns.rawlog"));
	EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1001, 1003}));
	ASSERT_EQ(r.problems.size(), 1u);
	EXPECT_NE(r.problems[0].message.find("beam count 2147483647"), std::string::npos) << r.problems[0].message;
	EXPECT_LT(peakRss_kB() - rssBefore_kB, 200 * 1024);
}

TEST(RawlogReader, AClassNamePaddedWithNulsDoesNotEscapeTheSizeChecks)
{
	// MRPT makes a C string of the stored class name, so
	// "mrpt::obs::CObservationRange" followed by three NULs (a header length
	// of 31) still reads as the range observation; a fuzzer made MRPT grow a
	// deque of 16.8 M sensors this way, past the 2 GB limit.
	hslam::testing::CTempDir tmp;
	mrpt::obs::CObservationRange sonar;
	sonar.sensorLabel = "SONAR";
	sonar.sensedData.resize(8);
	TBytes bytes = serialize(sonar);
	const size_t nameLength = std::strlen("mrpt::obs::CObservationRange");
	ASSERT_EQ(bytes[0], 0x80u | nameLength);
	bytes.insert(bytes.begin() + 1 + static_cast<long>(nameLength), 3, 0);
	bytes[0] = static_cast<uint8_t>(0x80u | (nameLength + 3));
	const size_t versionAt = 1 + nameLength + 3;
	putU32(bytes, versionAt + 1 + 12, 0x01010100u);  // 16.8 M sensors
	auto objs = scanObjects(3);
	objs.insert(objs.begin() + 1, bytes);
	writeFile(tmp.file("nuls.rawlog"), objs, false);
	const long rssBefore_kB = peakRss_kB();
	const auto r = readAll(tmp.file("nuls.rawlog"));
	EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1001, 1002}));
	ASSERT_EQ(r.problems.size(), 1u);
	EXPECT_NE(r.problems[0].message.find("range sensor count 16843008"), std::string::npos) << r.problems[0].message;
	EXPECT_LT(peakRss_kB() - rssBefore_kB, 200 * 1024);
}

TEST(RawlogReader, BytesInsideAFieldThatLookLikeAHeaderAreData)
{
	// MRPT reads a header only where an object starts. A recorded rawlog had a
	// timestamp byte 0xA7 just before the next object's header, which together
	// looked like a header named "...mrpt::obs::CObservationComment" with an
	// absurd comment length; the reader refused it and lost the battery
	// reading around it. Here the same bytes sit inside a comment's text.
	hslam::testing::CTempDir tmp;
	const std::string name = "mrpt::obs::CObservationComment";
	std::string fake(1, static_cast<char>(0x80u | name.size()));
	fake += name;
	fake += std::string("\0\xff\xff\xff\x7f", 5);  // version 0, comment length 2 GB
	mrpt::obs::CObservationComment comment;
	comment.text = "before " + fake + " after";
	comment.timestamp = mrpt::Clock::fromDouble(1000.5);
	auto objs = scanObjects(3);
	objs.insert(objs.begin() + 1, serialize(comment));
	writeFile(tmp.file("fake-header.rawlog"), objs, true);

	const auto r = readAll(tmp.file("fake-header.rawlog"));
	EXPECT_EQ(r.error, "");
	EXPECT_TRUE(r.problems.empty()) << r.problems.front().message;
	EXPECT_EQ(r.stamps, (std::vector<double>{1000, 1000.5, 1001, 1002}));
	CRawlogReader reader(tmp.file("fake-header.rawlog"));
	TRawlogEntry e;
	ASSERT_TRUE(reader.next(e) && reader.next(e));
	const auto read = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(e.observation);
	ASSERT_TRUE(read);
	EXPECT_EQ(read->text, comment.text);
}
