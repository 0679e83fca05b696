/* Tests of the ARCOS codec against hand-built byte sequences, and a randomized
 * fuzz test of the stream parser (garbage, truncation, corruption, resync). */
#include <gtest/gtest.h>
#include <hslam/hwdrivers/arcos_protocol.h>

#include <random>

using namespace hslam::hwdrivers::arcos;
using Bytes = std::vector<uint8_t>;

TEST(ArcosProtocol, ChecksumWorkedExamples)
{
	// VEL +200 mm/s (notes s.3): FA FB 06 0B 3B C8 00 D3 3B.
	EXPECT_EQ(encodeCommandInt(CMD_VEL, 200), (Bytes{0xFA, 0xFB, 0x06, 0x0B, 0x3B, 0xC8, 0x00, 0xD3, 0x3B}));
	// SYNC packets: odd payload -> the last byte is XORed in.
	EXPECT_EQ(encodeCommand(CMD_SYNC0), (Bytes{0xFA, 0xFB, 0x03, 0x00, 0x00, 0x00}));
	EXPECT_EQ(encodeCommand(CMD_SYNC1), (Bytes{0xFA, 0xFB, 0x03, 0x01, 0x00, 0x01}));
	EXPECT_EQ(encodeCommand(CMD_SYNC2), (Bytes{0xFA, 0xFB, 0x03, 0x02, 0x00, 0x02}));
	// Odd payload of 3 bytes: 0x0102 ^ 0x03 = 0x0101.
	EXPECT_EQ(checksum(Bytes{0x01, 0x02, 0x03}), 0x0101);
	// Sum wraps modulo 2^16: 0xFFFF + 0x0002 = 0x0001.
	EXPECT_EQ(checksum(Bytes{0xFF, 0xFF, 0x00, 0x02}), 0x0001);
}

TEST(ArcosProtocol, NegativeIntegerIsSentAsMagnitude)
{
	// RVEL -30 deg/s: 15 1B 1E 00, checksum 0x151B + 0x1E00 = 0x331B.
	EXPECT_EQ(encodeCommandInt(CMD_RVEL, -30), (Bytes{0xFA, 0xFB, 0x06, 0x15, 0x1B, 0x1E, 0x00, 0x33, 0x1B}));
	const auto c = decodeCommand(Bytes{0x15, 0x1B, 0x1E, 0x00});
	ASSERT_TRUE(c);
	EXPECT_EQ(c->command, CMD_RVEL);
	EXPECT_EQ(c->arg, TCommand::INT);
	EXPECT_EQ(c->intValue, -30);
	// 300 mm/s = 0x012C, little-endian.
	const auto v = decodeCommand(Bytes{0x0B, 0x3B, 0x2C, 0x01});
	ASSERT_TRUE(v);
	EXPECT_EQ(v->intValue, 300);
	EXPECT_THROW(encodeCommandInt(CMD_VEL, 70000), std::out_of_range);
	EXPECT_FALSE(decodeCommand(Bytes{0x0B, 0x3B, 0x2C}));  // truncated argument
}

TEST(ArcosProtocol, StringArgument)
{
	const Bytes p = encodeCommandString(42, "abc");
	// 0x2A2B + 0x0361 + 0x6263 = 0x8FEF.
	EXPECT_EQ(p, (Bytes{0xFA, 0xFB, 0x08, 0x2A, 0x2B, 0x03, 'a', 'b', 'c', 0x8F, 0xEF}));
	const auto c = decodeCommand(Bytes(p.begin() + 3, p.end() - 2));
	ASSERT_TRUE(c);
	EXPECT_EQ(c->stringValue, "abc");
}

TEST(ArcosProtocol, ParserSkipsGarbageAndBadChecksums)
{
	CArcosPacketParser parser;
	Bytes stream{'W', 'M', 'S', '2', '\r', 0xFA};  // Aria's modem wake-up + a stray header byte
	const Bytes vel = encodeCommandInt(CMD_VEL, 200);
	Bytes bad = vel;
	bad.back() ^= 1;  // corrupted checksum
	const Bytes rvel = encodeCommandInt(CMD_RVEL, -30);
	for (const Bytes* b : std::initializer_list<const Bytes*>{&vel, &bad, &rvel}) stream.insert(stream.end(), b->begin(), b->end());
	// Feed one byte at a time: framing must not depend on read boundaries.
	std::vector<Bytes> got;
	Bytes payload;
	for (uint8_t b : stream)
	{
		parser.feed(&b, 1);
		while (parser.next(payload)) got.push_back(payload);
	}
	ASSERT_EQ(got.size(), 2u);
	EXPECT_EQ(got[0], (Bytes{0x0B, 0x3B, 0xC8, 0x00}));
	EXPECT_EQ(got[1], (Bytes{0x15, 0x1B, 0x1E, 0x00}));
	EXPECT_EQ(parser.stats().packets, 2u);
	EXPECT_EQ(parser.stats().badChecksums, 1u);
	EXPECT_GE(parser.stats().garbageBytes, 6u);
	EXPECT_EQ(parser.pending(), 0u);
}

TEST(ArcosProtocol, ParserResyncsAfterTruncatedPacket)
{
	// A SIP cut in half (device reset mid-packet) followed by valid packets:
	// the truncated frame's declared length swallows the next packet, fails the
	// checksum, and the parser resyncs on the header inside it.
	Bytes big(60, 0x32);
	const Bytes full = framePacket(big);
	Bytes stream(full.begin(), full.begin() + 20);
	const Bytes a = encodeCommandInt(CMD_VEL, 100), b = encodeCommandInt(CMD_VEL, -100);
	for (int k = 0; k < 10; ++k)
	{
		stream.insert(stream.end(), a.begin(), a.end());
		stream.insert(stream.end(), b.begin(), b.end());
	}
	CArcosPacketParser parser;
	parser.feed(stream);
	Bytes payload;
	int n = 0;
	while (parser.next(payload)) ++n;
	EXPECT_EQ(n, 20);
	EXPECT_GE(parser.stats().badChecksums, 1u);
}

TEST(ArcosProtocol, ParserRejectsImpossibleLengths)
{
	CArcosPacketParser parser;
	Bytes s{0xFA, 0xFB, 0x01, 0xFA, 0xFB, 0xFF};  // N < 3 and N > 197
	const Bytes ok = encodeCommand(CMD_PULSE);
	s.insert(s.end(), ok.begin(), ok.end());
	parser.feed(s);
	Bytes payload;
	ASSERT_TRUE(parser.next(payload));
	EXPECT_EQ(payload, Bytes{0x00});
	EXPECT_EQ(parser.stats().badLengths, 2u);
}

TEST(ArcosProtocol, FuzzRandomStreamsNeverLoseValidPacketsOrCrash)
{
	std::mt19937 rng(12345);
	std::uniform_int_distribution<int> byte(0, 255), len(1, MAX_PAYLOAD_BYTES), coin(0, 9);
	size_t totalSent = 0, totalFound = 0;
	for (int round = 0; round < 300; ++round)
	{
		std::vector<Bytes> sent;
		Bytes stream;
		for (int k = 0; k < 20; ++k)
		{
			// Garbage, biased towards header bytes so fake headers are common.
			const int g = byte(rng) % 30;
			for (int i = 0; i < g; ++i)
			{
				const int r = coin(rng);
				stream.push_back(r < 2 ? 0xFA : r < 4 ? 0xFB : static_cast<uint8_t>(byte(rng)));
			}
			// Sometimes a truncated or corrupted packet.
			Bytes junk(static_cast<size_t>(len(rng)));
			for (auto& b : junk) b = static_cast<uint8_t>(byte(rng));
			Bytes framedJunk = framePacket(junk);
			if (coin(rng) < 3)
			{
				framedJunk.resize(static_cast<size_t>(byte(rng)) % framedJunk.size());
				stream.insert(stream.end(), framedJunk.begin(), framedJunk.end());
			}
			else if (coin(rng) < 3)
			{
				framedJunk[framedJunk.size() - 1 - coin(rng) % 2] ^= static_cast<uint8_t>(1 + byte(rng) % 255);
				stream.insert(stream.end(), framedJunk.begin(), framedJunk.end());
			}
			// The valid packet.
			Bytes p(static_cast<size_t>(len(rng)));
			for (auto& b : p) b = static_cast<uint8_t>(byte(rng));
			const Bytes f = framePacket(p);
			stream.insert(stream.end(), f.begin(), f.end());
			sent.push_back(p);
		}
		// Feed in random chunk sizes.
		CArcosPacketParser parser;
		std::vector<Bytes> got;
		Bytes payload;
		for (size_t i = 0; i < stream.size();)
		{
			const size_t n = std::min(stream.size() - i, static_cast<size_t>(1 + byte(rng) % 64));
			parser.feed(&stream[i], n);
			i += n;
			while (parser.next(payload)) got.push_back(payload);
			ASSERT_LE(parser.pending(), MAX_PACKET_BYTES);
		}
		// Every valid packet appears, in order (extra "packets" made of garbage
		// that happen to have a valid checksum are allowed).
		size_t j = 0;
		for (const auto& g : got)
			if (j < sent.size() && g == sent[j]) ++j;
		totalSent += sent.size();
		totalFound += j;
	}
	// Only a garbage frame that swallows a real packet AND passes the 16-bit
	// checksum (p ~ 1/65536 per fake header) can lose one.
	EXPECT_GE(static_cast<double>(totalFound), 0.999 * totalSent) << totalFound << " of " << totalSent;
}

TEST(ArcosProtocol, FuzzPureNoiseAndTruncations)
{
	std::mt19937 rng(7);
	for (int round = 0; round < 2000; ++round)
	{
		Bytes noise(static_cast<size_t>(rng() % 600));
		for (auto& b : noise) b = static_cast<uint8_t>(rng() % 4 == 0 ? 0xFA + rng() % 2 : rng());
		CArcosPacketParser parser;
		parser.feed(noise);
		Bytes payload;
		while (parser.next(payload))
		{
			ASSERT_GE(payload.size(), 1u);
			ASSERT_LE(payload.size(), MAX_PAYLOAD_BYTES);
			decodeCommand(payload);  // must not crash on any payload
		}
		ASSERT_LE(parser.pending(), MAX_PACKET_BYTES);
	}
}
