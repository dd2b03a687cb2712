#pragma once
// A small reader and writer for MCAP files (https://mcap.dev/spec), the recording format that
// robotics tools open (Foxglove Studio, eProsima DDS Record & Replay, the mcap CLI).
//
// Written files are unchunked and uncompressed: Header, then Schema / Channel / Message /
// Attachment / Metadata records in the order they were written, DataEnd with the CRC-32 of the
// data section, a summary section (Schema, Channel, Statistics, Attachment index, Metadata index
// records, and Summary Offset records), and the Footer with the summary CRC. The output depends
// only on what was written, never on wall-clock time, so equal inputs give byte-identical files.
//
// The reader accepts any valid MCAP file: unchunked records, and chunks with compression ""
// (chunks with zstd or lz4 compression are reported as an error naming the compression).

#include <cstdint>
#include <fstream>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace entourage::mcap {

struct Schema {
  std::uint16_t id = 0;
  std::string name;      // e.g. "entourage::msg::VehicleState"
  std::string encoding;  // e.g. "omgidl"
  std::string data;      // e.g. the IDL text
};

struct Channel {
  std::uint16_t id = 0;
  std::uint16_t schema_id = 0;
  std::string topic;             // e.g. "entourage/vehicle_state"
  std::string message_encoding;  // e.g. "cdr"
  std::map<std::string, std::string> metadata;
};

struct Message {
  std::uint16_t channel_id = 0;
  std::uint32_t sequence = 0;
  std::uint64_t log_time_ns = 0;
  std::uint64_t publish_time_ns = 0;
  std::vector<std::uint8_t> data;
};

struct Attachment {
  std::uint64_t log_time_ns = 0;
  std::uint64_t create_time_ns = 0;
  std::string name;
  std::string media_type;
  std::string data;
};

struct Metadata {
  std::string name;
  std::map<std::string, std::string> entries;
};

class Writer {
 public:
  Writer() = default;
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;
  ~Writer();  // closes the file if still open

  // Creates (truncates) the file and writes the magic and the Header record.
  // Returns false and sets error() if the file cannot be created.
  bool open(const std::string& path, const std::string& profile, const std::string& library);

  // Registers a schema or channel; ids are assigned by the caller and must be unique (>0 for
  // schemas). Each is written to the data section at once and repeated in the summary.
  void add_schema(const Schema& schema);
  void add_channel(const Channel& channel);
  void write(const Message& message);
  void add_attachment(const Attachment& attachment);
  void add_metadata(const Metadata& metadata);

  // Writes DataEnd, the summary section and the Footer, then closes. Returns false on I/O error.
  bool close();

  bool is_open() const { return out_.is_open(); }
  const std::string& error() const { return error_; }
  std::uint64_t message_count() const { return message_count_; }

 private:
  struct AttachmentIndexEntry {
    std::uint64_t offset, length, log_time_ns, create_time_ns, data_size;
    std::string name, media_type;
  };
  struct MetadataIndexEntry {
    std::uint64_t offset, length;
    std::string name;
  };
  void write_record(std::uint8_t opcode, const std::string& body, bool data_section);
  std::string statistics_body() const;
  // The summary and summary offset sections, the Footer and the trailing magic.
  std::string summary_and_footer(std::uint64_t summary_start) const;

  std::ofstream out_;
  std::string path_;
  std::string error_;
  std::uint32_t data_crc_ = 0;
  std::uint64_t position_ = 0;
  std::vector<Schema> schemas_;
  std::vector<Channel> channels_;
  std::map<std::uint16_t, std::uint64_t> channel_message_counts_;
  std::vector<AttachmentIndexEntry> attachment_index_;
  std::vector<MetadataIndexEntry> metadata_index_;
  std::uint64_t message_count_ = 0;
  std::uint64_t message_start_time_ = 0;
  std::uint64_t message_end_time_ = 0;
};

// Everything in a file, in file order for messages. Suitable for recordings that fit in memory.
struct Contents {
  std::string profile;
  std::string library;
  std::map<std::uint16_t, Schema> schemas;
  std::map<std::uint16_t, Channel> channels;
  std::vector<Message> messages;
  std::vector<Attachment> attachments;
  std::vector<Metadata> metadata;
};

// Reads a whole file. Returns std::nullopt and sets *error to a message naming the file and the
// byte offset of the problem (bad magic, truncated record, CRC mismatch, unsupported
// compression) on failure.
std::optional<Contents> read_file(const std::string& path, std::string* error);

}  // namespace entourage::mcap
