// Unit tests for the MCAP reader and writer (common/mcap). Files go to a per-test directory
// under the system temp directory; CRCs are checked against an independent CRC-32 below.
#include "mcap/mcap.hpp"

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace entourage::mcap {
namespace {

namespace fs = std::filesystem;

const std::string kMagic("\x89MCAP0\r\n", 8);

// A fresh directory per test (and per process, so parallel runs do not collide).
class McapTest : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::temp_directory_path() /
           ("entourage_mcap_test_" + std::string(info->name()) + "_" + std::to_string(::getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }
  std::string path(const std::string& name) const { return (dir_ / name).string(); }

  fs::path dir_;
};

std::string read_bytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return bytes.str();
}

void write_bytes(const std::string& path, const std::string& bytes) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

// Bitwise CRC-32 (IEEE, reflected), independent of the zlib used by the implementation.
std::uint32_t crc32_of(const std::string& bytes) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char c : bytes) {
    crc ^= static_cast<unsigned char>(c);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

std::uint64_t read_u64(const std::string& bytes, std::size_t at) {
  std::uint64_t value = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    value |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[at + i])) << (8 * i);
  }
  return value;
}

// Builds MCAP bytes by hand, independently of the writer.
class Bytes {
 public:
  Bytes& u8(std::uint8_t v) { return le(v, 1); }
  Bytes& u16(std::uint16_t v) { return le(v, 2); }
  Bytes& u32(std::uint32_t v) { return le(v, 4); }
  Bytes& u64(std::uint64_t v) { return le(v, 8); }
  Bytes& str(const std::string& s) {
    u32(static_cast<std::uint32_t>(s.size()));
    return raw(s);
  }
  Bytes& raw(const std::string& s) {
    bytes_ += s;
    return *this;
  }
  Bytes& record(std::uint8_t opcode, const Bytes& body) {
    u8(opcode).u64(body.size());
    return raw(body.bytes_);
  }
  const std::string& str() const { return bytes_; }
  std::size_t size() const { return bytes_.size(); }

 private:
  Bytes& le(std::uint64_t v, int n) {
    for (int i = 0; i < n; ++i) bytes_.push_back(static_cast<char>((v >> (8 * i)) & 0xFFu));
    return *this;
  }
  std::string bytes_;
};

Schema vehicle_schema() { return {1, "entourage::msg::VehicleState", "omgidl", "struct V {};"}; }

Channel vehicle_channel() {
  return {3, 1, "entourage/vehicle_state", "cdr", {{"qos", "reliable"}, {"rate_hz", "50"}}};
}

Message make_message(std::uint16_t channel, std::uint32_t sequence, std::size_t size) {
  Message m;
  m.channel_id = channel;
  m.sequence = sequence;
  m.log_time_ns = 1'000'000'000ull + 10'000'000ull * sequence;
  m.publish_time_ns = m.log_time_ns - 5;
  for (std::size_t i = 0; i < size; ++i) {
    m.data.push_back(static_cast<std::uint8_t>(i * 7 + sequence));
  }
  return m;
}

// A deterministic recording with a bit of everything.
void write_sample(const std::string& file) {
  Writer writer;
  ASSERT_TRUE(writer.open(file, "entourage", "entourage-test")) << writer.error();
  writer.add_schema(vehicle_schema());
  writer.add_schema({2, "entourage::msg::Light", "omgidl", "struct L { long state; };"});
  writer.add_channel(vehicle_channel());
  writer.add_channel({4, 2, "entourage/lights", "cdr", {}});
  for (std::uint32_t i = 0; i < 20; ++i) writer.write(make_message(i % 2 ? 4 : 3, i, i * 3));
  writer.add_attachment({5, 6, "scenario.yaml", "application/yaml", "vehicles: 3\n"});
  writer.add_metadata({"run", {{"seed", "42"}, {"scenario", "ring"}}});
  ASSERT_TRUE(writer.close()) << writer.error();
}

void expect_equal(const Message& a, const Message& b) {
  EXPECT_EQ(a.channel_id, b.channel_id);
  EXPECT_EQ(a.sequence, b.sequence);
  EXPECT_EQ(a.log_time_ns, b.log_time_ns);
  EXPECT_EQ(a.publish_time_ns, b.publish_time_ns);
  EXPECT_TRUE(a.data == b.data) << "data of message " << a.sequence << " differs";
}

TEST_F(McapTest, RoundTripsSchemasChannelsAndMessages) {
  const std::string file = path("round_trip.mcap");
  std::vector<Message> written;
  for (std::uint32_t i = 0; i < 500; ++i) written.push_back(make_message(i % 3 ? 3 : 4, i, i % 50));
  written.push_back(make_message(3, 900, 0));
  written.push_back(make_message(4, 901, 1 << 20));
  written.push_back(make_message(3, 902, 0));
  written[10].log_time_ns = 5;  // out of order on purpose
  Writer writer;
  ASSERT_TRUE(writer.open(file, "entourage", "entourage-test")) << writer.error();
  writer.add_schema(vehicle_schema());
  writer.add_channel(vehicle_channel());
  writer.add_channel({4, 0, "entourage/raw", "", {}});
  for (const Message& m : written) writer.write(m);
  EXPECT_EQ(writer.message_count(), written.size());
  ASSERT_TRUE(writer.close()) << writer.error();
  EXPECT_FALSE(writer.is_open());

  std::string error;
  const auto contents = read_file(file, &error);
  ASSERT_TRUE(contents) << error;
  EXPECT_EQ(contents->profile, "entourage");
  EXPECT_EQ(contents->library, "entourage-test");
  ASSERT_EQ(contents->schemas.size(), 1u);
  const Schema& schema = contents->schemas.at(1);
  EXPECT_EQ(schema.name, "entourage::msg::VehicleState");
  EXPECT_EQ(schema.encoding, "omgidl");
  EXPECT_EQ(schema.data, "struct V {};");
  ASSERT_EQ(contents->channels.size(), 2u);
  const Channel& channel = contents->channels.at(3);
  EXPECT_EQ(channel.schema_id, 1);
  EXPECT_EQ(channel.topic, "entourage/vehicle_state");
  EXPECT_EQ(channel.message_encoding, "cdr");
  EXPECT_EQ(channel.metadata, vehicle_channel().metadata);
  EXPECT_EQ(contents->channels.at(4).schema_id, 0);
  ASSERT_EQ(contents->messages.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) expect_equal(contents->messages[i], written[i]);
  EXPECT_EQ(contents->messages[written.size() - 2].data.size(), 1u << 20);
}

TEST_F(McapTest, RoundTripsAttachmentsAndMetadata) {
  const std::string file = path("attachments.mcap");
  Writer writer;
  ASSERT_TRUE(writer.open(file, "", "")) << writer.error();
  writer.add_attachment({100, 50, "scenario.yaml", "application/yaml", "vehicles: 3\n"});
  writer.add_attachment({200, 0, "empty.bin", "application/octet-stream", ""});
  const std::string binary("\0\x01\xff", 3);
  writer.add_attachment({300, 1, "binary.bin", "application/octet-stream", binary});
  writer.add_metadata({"run", {{"seed", "42"}, {"scenario", "ring"}}});
  writer.add_metadata({"empty", {}});
  ASSERT_TRUE(writer.close()) << writer.error();

  std::string error;
  const auto contents = read_file(file, &error);
  ASSERT_TRUE(contents) << error;
  EXPECT_TRUE(contents->messages.empty());
  ASSERT_EQ(contents->attachments.size(), 3u);
  EXPECT_EQ(contents->attachments[0].log_time_ns, 100u);
  EXPECT_EQ(contents->attachments[0].create_time_ns, 50u);
  EXPECT_EQ(contents->attachments[0].name, "scenario.yaml");
  EXPECT_EQ(contents->attachments[0].media_type, "application/yaml");
  EXPECT_EQ(contents->attachments[0].data, "vehicles: 3\n");
  EXPECT_EQ(contents->attachments[1].data, "");
  EXPECT_EQ(contents->attachments[2].data, binary);
  ASSERT_EQ(contents->metadata.size(), 2u);
  EXPECT_EQ(contents->metadata[0].name, "run");
  EXPECT_EQ(contents->metadata[0].entries.at("seed"), "42");
  EXPECT_EQ(contents->metadata[0].entries.at("scenario"), "ring");
  EXPECT_EQ(contents->metadata[1].name, "empty");
  EXPECT_TRUE(contents->metadata[1].entries.empty());
}

TEST_F(McapTest, IdenticalWritesGiveIdenticalBytes) {
  write_sample(path("a.mcap"));
  write_sample(path("b.mcap"));
  const std::string a = read_bytes(path("a.mcap"));
  EXPECT_GT(a.size(), 100u);
  EXPECT_TRUE(a == read_bytes(path("b.mcap")));
}

TEST_F(McapTest, StartsWithMagicAndHeaderRecord) {
  write_sample(path("header.mcap"));
  const std::string bytes = read_bytes(path("header.mcap"));
  const std::string expected =
      Bytes().raw(kMagic).record(0x01, Bytes().str("entourage").str("entourage-test")).str();
  ASSERT_GE(bytes.size(), expected.size());
  EXPECT_EQ(bytes.substr(0, expected.size()), expected);
  EXPECT_EQ(bytes.substr(bytes.size() - 8), kMagic);
}

TEST_F(McapTest, FooterAndCrcsMatchAnIndependentCrc) {
  write_sample(path("crc.mcap"));
  const std::string bytes = read_bytes(path("crc.mcap"));
  // Footer: opcode, length 20, summary_start, summary_offset_start, summary_crc; then magic.
  const std::size_t footer = bytes.size() - 8 - 29;
  ASSERT_EQ(bytes[footer], '\x02');
  EXPECT_EQ(read_u64(bytes, footer + 1), 20u);
  const std::uint64_t summary_start = read_u64(bytes, footer + 9);
  const std::uint64_t summary_offset_start = read_u64(bytes, footer + 17);
  ASSERT_LT(summary_start, summary_offset_start);
  ASSERT_LT(summary_offset_start, footer);
  const std::string summary = bytes.substr(summary_start, footer + 25 - summary_start);
  EXPECT_EQ(bytes.substr(footer + 25, 4), Bytes().u32(crc32_of(summary)).str());
  // DataEnd (opcode 0x0F, length 4) sits right before the summary; its CRC covers all before it.
  const std::size_t data_end = summary_start - 13;
  EXPECT_EQ(bytes.substr(data_end, 9), Bytes().u8(0x0F).u64(4).str());
  EXPECT_EQ(bytes.substr(data_end + 9, 4), Bytes().u32(crc32_of(bytes.substr(0, data_end))).str());
  // The summary starts with the Schema group (opcode 0x03).
  EXPECT_EQ(bytes[summary_start], '\x03');
  EXPECT_EQ(bytes[summary_offset_start], '\x0E');
}

TEST_F(McapTest, RejectsTruncatedFileNamingTheOffset) {
  write_sample(path("full.mcap"));
  const std::string bytes = read_bytes(path("full.mcap"));
  const std::string file = path("truncated.mcap");
  std::string error;

  write_bytes(file, bytes.substr(0, 20));  // inside the Header record, which starts at 8
  EXPECT_FALSE(read_file(file, &error));
  EXPECT_NE(error.find(file), std::string::npos) << error;
  EXPECT_NE(error.find("truncated"), std::string::npos) << error;
  EXPECT_NE(error.find("offset 8"), std::string::npos) << error;

  write_bytes(file, bytes.substr(0, bytes.size() / 2));
  error.clear();
  EXPECT_FALSE(read_file(file, &error));
  EXPECT_NE(error.find(file), std::string::npos) << error;
  EXPECT_NE(error.find("offset "), std::string::npos) << error;

  write_bytes(file, bytes.substr(0, bytes.size() - 3));  // trailing magic cut short
  error.clear();
  EXPECT_FALSE(read_file(file, &error));
  EXPECT_NE(error.find("offset " + std::to_string(bytes.size() - 8)), std::string::npos) << error;
}

TEST_F(McapTest, RejectsBadLeadingMagic) {
  write_sample(path("full.mcap"));
  std::string bytes = read_bytes(path("full.mcap"));
  bytes[1] = 'X';
  write_bytes(path("bad.mcap"), bytes);
  std::string error;
  EXPECT_FALSE(read_file(path("bad.mcap"), &error));
  EXPECT_NE(error.find("magic"), std::string::npos) << error;
  EXPECT_NE(error.find("offset 0"), std::string::npos) << error;
}

TEST_F(McapTest, RejectsFlippedByteInDataSectionByCrc) {
  const std::string file = path("flipped.mcap");
  Writer writer;
  ASSERT_TRUE(writer.open(file, "", ""));
  writer.add_channel({1, 0, "t", "", {}});
  Message m = make_message(1, 0, 0);
  m.data.assign({'p', 'a', 'y', 'l', 'o', 'a', 'd'});
  writer.write(m);
  ASSERT_TRUE(writer.close());
  std::string bytes = read_bytes(file);
  const std::size_t at = bytes.find("payload");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'P';
  write_bytes(file, bytes);
  std::string error;
  EXPECT_FALSE(read_file(file, &error));
  EXPECT_NE(error.find("data section CRC"), std::string::npos) << error;
  EXPECT_NE(error.find(file), std::string::npos) << error;
}

TEST_F(McapTest, RejectsFlippedByteInSummaryByCrc) {
  write_sample(path("full.mcap"));
  std::string bytes = read_bytes(path("full.mcap"));
  const std::size_t footer = bytes.size() - 8 - 29;
  const std::uint64_t summary_start = read_u64(bytes, footer + 9);
  bytes[summary_start + 15] ^= 0x01;  // in the name of the first summary Schema
  write_bytes(path("bad.mcap"), bytes);
  std::string error;
  EXPECT_FALSE(read_file(path("bad.mcap"), &error));
  EXPECT_NE(error.find("summary CRC"), std::string::npos) << error;
}

TEST_F(McapTest, RejectsCorruptAttachmentByItsCrc) {
  write_sample(path("full.mcap"));
  std::string bytes = read_bytes(path("full.mcap"));
  const std::size_t at = bytes.find("vehicles: 3");
  ASSERT_NE(at, std::string::npos);
  bytes[at] = 'V';
  write_bytes(path("bad.mcap"), bytes);
  std::string error;
  EXPECT_FALSE(read_file(path("bad.mcap"), &error));
  EXPECT_NE(error.find("attachment \"scenario.yaml\" CRC"), std::string::npos) << error;
}

// Header, an uncompressed Chunk holding Schema, Channel and two Messages, their Message Index,
// an unknown application record, DataEnd, a summary with a Chunk Index, Footer.
std::string hand_built_chunked_file(const std::string& compression, bool with_crcs) {
  Bytes inner;
  inner.record(0x03, Bytes().u16(7).str("S").str("jsonschema").str("{}"));
  inner.record(0x04, Bytes().u16(2).u16(7).str("/pose").str("json").u32(0));
  const std::size_t first = inner.size();
  inner.record(0x05, Bytes().u16(2).u32(1).u64(100).u64(99).raw("{\"x\":1}"));
  const std::size_t second = inner.size();
  inner.record(0x05, Bytes().u16(2).u32(2).u64(200).u64(199).raw(""));

  Bytes file;
  file.raw(kMagic).record(0x01, Bytes().str("").str("hand"));
  const std::size_t chunk_start = file.size();
  file.record(0x06, Bytes().u64(100).u64(200).u64(inner.size())
                        .u32(with_crcs ? crc32_of(inner.str()) : 0).str(compression)
                        .u64(inner.size()).raw(inner.str()));
  const std::size_t chunk_length = file.size() - chunk_start;
  const std::size_t index_start = file.size();
  file.record(0x07, Bytes().u16(2).u32(32).u64(100).u64(first).u64(200).u64(second));
  const std::size_t index_length = file.size() - index_start;
  file.record(0x80, Bytes().raw("application extension"));
  file.record(0x0F, Bytes().u32(with_crcs ? crc32_of(file.str()) : 0));

  const std::size_t summary_start = file.size();
  file.record(0x03, Bytes().u16(7).str("S").str("jsonschema").str("{}"));
  file.record(0x04, Bytes().u16(2).u16(7).str("/pose").str("json").u32(0));
  file.record(0x08, Bytes().u64(100).u64(200).u64(chunk_start).u64(chunk_length)
                        .u32(10).u16(2).u64(index_start).u64(index_length)
                        .str(compression).u64(inner.size()).u64(inner.size()));
  file.u8(0x02).u64(20).u64(summary_start).u64(0);
  file.u32(with_crcs ? crc32_of(file.str().substr(summary_start)) : 0);
  return file.raw(kMagic).str();
}

TEST_F(McapTest, ReadsHandBuiltUncompressedChunk) {
  for (const bool with_crcs : {false, true}) {
    const std::string file = path(with_crcs ? "chunk_crc.mcap" : "chunk.mcap");
    write_bytes(file, hand_built_chunked_file("", with_crcs));
    std::string error;
    const auto contents = read_file(file, &error);
    ASSERT_TRUE(contents) << error;
    EXPECT_EQ(contents->library, "hand");
    ASSERT_EQ(contents->schemas.size(), 1u);
    EXPECT_EQ(contents->schemas.at(7).encoding, "jsonschema");
    ASSERT_EQ(contents->channels.size(), 1u);
    EXPECT_EQ(contents->channels.at(2).topic, "/pose");
    ASSERT_EQ(contents->messages.size(), 2u);
    EXPECT_EQ(contents->messages[0].sequence, 1u);
    EXPECT_EQ(contents->messages[0].log_time_ns, 100u);
    EXPECT_EQ(contents->messages[0].publish_time_ns, 99u);
    const std::string json = "{\"x\":1}";
    const std::vector<std::uint8_t>& data = contents->messages[0].data;
    EXPECT_EQ(std::string(data.begin(), data.end()), json);
    EXPECT_EQ(contents->messages[1].log_time_ns, 200u);
    EXPECT_TRUE(contents->messages[1].data.empty());
  }
}

TEST_F(McapTest, RejectsCompressedChunkNamingTheCompression) {
  const std::string file = path("zstd.mcap");
  write_bytes(file, hand_built_chunked_file("zstd", true));
  std::string error;
  EXPECT_FALSE(read_file(file, &error));
  EXPECT_NE(error.find("\"zstd\""), std::string::npos) << error;
  EXPECT_NE(error.find(file), std::string::npos) << error;
  const std::size_t chunk_start = 8 + 9 + 4 + 4 + 4;  // after magic and the Header record
  EXPECT_NE(error.find("offset " + std::to_string(chunk_start)), std::string::npos) << error;
}

TEST_F(McapTest, EmptyRecordingIsValid) {
  Writer writer;
  ASSERT_TRUE(writer.open(path("empty.mcap"), "", ""));
  ASSERT_TRUE(writer.close()) << writer.error();
  std::string error;
  const auto contents = read_file(path("empty.mcap"), &error);
  ASSERT_TRUE(contents) << error;
  EXPECT_TRUE(contents->messages.empty());
  EXPECT_TRUE(contents->schemas.empty());
}

TEST_F(McapTest, ReadingNonexistentFileNamesIt) {
  const std::string file = path("does_not_exist.mcap");
  std::string error;
  EXPECT_FALSE(read_file(file, &error));
  EXPECT_NE(error.find(file), std::string::npos) << error;
  EXPECT_FALSE(read_file(file, nullptr));
}

TEST_F(McapTest, OpeningInMissingDirectoryFails) {
  Writer writer;
  EXPECT_FALSE(writer.open(path("missing/dir/x.mcap"), "", ""));
  EXPECT_FALSE(writer.is_open());
  EXPECT_NE(writer.error().find("missing/dir/x.mcap"), std::string::npos) << writer.error();
  EXPECT_FALSE(writer.close());
}

}  // namespace
}  // namespace entourage::mcap
