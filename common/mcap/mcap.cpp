// MCAP reader and writer, following the MCAP format specification (https://mcap.dev/spec):
// a file is the magic, records of <opcode u8><content length u64><content>, and the magic again.
// Integers are little-endian; strings, byte arrays and maps carry a u32 byte-length prefix
// (attachment data and chunk records a u64 one); CRCs are CRC-32 as computed by zlib's crc32.
#include "mcap/mcap.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdio>
#include <utility>

namespace entourage::mcap {
namespace {

constexpr char kMagic[] = "\x89MCAP0\r\n";
constexpr std::uint64_t kMagicSize = sizeof(kMagic) - 1;
constexpr std::uint64_t kRecordPrefix = 9;  // opcode + content length

// Record opcodes (the spec's "Records" section); Message Index (0x07) and Chunk Index (0x08)
// are only ever skipped.
enum Opcode : std::uint8_t {
  kHeader = 0x01, kFooter = 0x02, kSchema = 0x03, kChannel = 0x04, kMessage = 0x05,
  kChunk = 0x06, kAttachment = 0x09, kAttachmentIndex = 0x0A, kStatistics = 0x0B,
  kMetadata = 0x0C, kMetadataIndex = 0x0D, kSummaryOffset = 0x0E, kDataEnd = 0x0F,
};

std::uint32_t crc_update(std::uint32_t crc, const char* data, std::uint64_t size) {
  constexpr std::uint64_t kStep = std::uint64_t{1} << 30;  // zlib takes uInt lengths
  while (size > 0) {
    const std::uint64_t n = std::min(size, kStep);
    crc = static_cast<std::uint32_t>(
        ::crc32(crc, reinterpret_cast<const Bytef*>(data), static_cast<uInt>(n)));
    data += n;
    size -= n;
  }
  return crc;
}

std::uint32_t crc_of(const std::string& bytes, std::uint64_t begin, std::uint64_t end) {
  return crc_update(0, bytes.data() + begin, end - begin);
}

// ---- Serialization -------------------------------------------------------------------------

template <typename T>
void put(std::string& out, T value) {
  for (std::size_t i = 0; i < sizeof(T); ++i) {
    out.push_back(static_cast<char>((value >> (8 * i)) & 0xFFu));
  }
}

// Serializes one field by its type: integers fixed-width, strings and maps length-prefixed.
void put_field(std::string& out, const std::string& text) {
  put<std::uint32_t>(out, static_cast<std::uint32_t>(text.size()));
  out += text;
}
template <typename T>
void put_field(std::string& out, T value) {
  put<T>(out, value);
}
template <typename K, typename V>
void put_field(std::string& out, const std::map<K, V>& map) {
  std::string entries;
  for (const auto& [key, value] : map) {
    put_field(entries, key);
    put_field(entries, value);
  }
  put_field(out, entries);  // a map is length-prefixed exactly like a string
}

template <typename... Fields>
std::string body_of(const Fields&... fields) {
  std::string body;
  (put_field(body, fields), ...);
  return body;
}

std::string record_bytes(std::uint8_t opcode, const std::string& body) {
  std::string out;
  out.reserve(kRecordPrefix + body.size());
  put<std::uint8_t>(out, opcode);
  put<std::uint64_t>(out, body.size());
  return out += body;
}

std::string schema_body(const Schema& s) { return body_of(s.id, s.name, s.encoding, s.data); }

std::string channel_body(const Channel& c) {
  return body_of(c.id, c.schema_id, c.topic, c.message_encoding, c.metadata);
}

// ---- Parsing -------------------------------------------------------------------------------

// A parse failure at an absolute byte offset in the file; turned into the error message.
struct ParseError {
  std::uint64_t offset;
  std::string message;
};

void check_crc(std::uint32_t stored, std::uint32_t computed, std::uint64_t offset,
               const std::string& what) {
  if (stored == 0 || stored == computed) return;  // 0 means "not computed"
  char text[64];
  std::snprintf(text, sizeof(text), " CRC mismatch (stored 0x%08x, computed 0x%08x)",
                static_cast<unsigned>(stored), static_cast<unsigned>(computed));
  throw ParseError{offset, what + text};
}

// Bounds-checked little-endian reads from [pos, end) of the file's bytes.
class Cursor {
 public:
  Cursor(const std::string& bytes, std::uint64_t begin, std::uint64_t end)
      : bytes_(&bytes), pos_(begin), end_(end) {}

  std::uint64_t pos() const { return pos_; }
  std::uint64_t remaining() const { return end_ - pos_; }

  template <typename T>
  T get() {
    const char* raw = take(sizeof(T));
    T value = 0;
    for (std::size_t i = 0; i < sizeof(T); ++i) {
      const auto byte = static_cast<std::uint64_t>(static_cast<unsigned char>(raw[i]));
      value = static_cast<T>(value | static_cast<T>(byte << (8 * i)));
    }
    return value;
  }

  const char* take(std::uint64_t n) {
    if (n > remaining()) {
      throw ParseError{pos_, "field of " + std::to_string(n) + " bytes runs past the end of its " +
                                 "record (" + std::to_string(remaining()) + " bytes left)"};
    }
    const char* raw = bytes_->data() + pos_;
    pos_ += n;
    return raw;
  }

  std::string bytes(std::uint64_t n) { return std::string(take(n), n); }
  std::string string() { return bytes(get<std::uint32_t>()); }

  Cursor sub(std::uint64_t n) {
    const std::uint64_t begin = pos_;
    take(n);
    return Cursor(*bytes_, begin, begin + n);
  }

 private:
  const std::string* bytes_;
  std::uint64_t pos_;
  std::uint64_t end_;
};

std::map<std::string, std::string> read_string_map(Cursor& cursor) {
  Cursor entries = cursor.sub(cursor.get<std::uint32_t>());
  std::map<std::string, std::string> map;
  while (entries.remaining() > 0) {
    std::string key = entries.string();
    map[std::move(key)] = entries.string();
  }
  return map;
}

// Parses a whole file held in memory into Contents, throwing ParseError on malformed input.
class FileParser {
 public:
  explicit FileParser(const std::string& file) : file_(file) {}

  Contents parse() {
    if (file_.size() < kMagicSize || file_.compare(0, kMagicSize, kMagic, kMagicSize) != 0) {
      throw ParseError{0, "bad leading magic (not an MCAP file)"};
    }
    Cursor cursor(file_, kMagicSize, file_.size());
    records(cursor, false);
    if (!footer_seen_) {
      throw ParseError{file_.size(), "file ends without a Footer record (truncated?)"};
    }
    if (cursor.remaining() != kMagicSize ||
        file_.compare(cursor.pos(), kMagicSize, kMagic, kMagicSize) != 0) {
      throw ParseError{cursor.pos(), "bad trailing magic after the Footer"};
    }
    return std::move(contents_);
  }

 private:
  void records(Cursor& cursor, bool in_chunk) {
    while (cursor.remaining() > 0 && !footer_seen_) {
      const std::uint64_t start = cursor.pos();
      if (cursor.remaining() < kRecordPrefix) {
        throw ParseError{start, "truncated record header (" + std::to_string(cursor.remaining()) +
                                    " bytes left)"};
      }
      const auto opcode = cursor.get<std::uint8_t>();
      const auto length = cursor.get<std::uint64_t>();
      if (length > cursor.remaining()) {
        throw ParseError{start, "truncated record: opcode " + std::to_string(opcode) +
                                    " claims " + std::to_string(length) + " bytes but only " +
                                    std::to_string(cursor.remaining()) + " are left"};
      }
      Cursor body = cursor.sub(length);
      if (!in_chunk && !header_seen_ && opcode != kHeader) {
        throw ParseError{start, "expected the Header record, found opcode " +
                                    std::to_string(opcode)};
      }
      record(opcode, body, start, in_chunk);
    }
  }

  void record(std::uint8_t opcode, Cursor& body, std::uint64_t start, bool in_chunk) {
    if (in_chunk && opcode != kSchema && opcode != kChannel && opcode != kMessage) return;
    switch (opcode) {
      case 0: throw ParseError{start, "invalid opcode 0"};
      case kHeader: header(body); break;
      case kFooter: footer(body, start); break;
      case kSchema: schema(body); break;
      case kChannel: channel(body); break;
      case kMessage: message(body); break;
      case kChunk: chunk(body, start); break;
      case kAttachment: attachment(body, start); break;
      case kMetadata: metadata(body); break;
      case kDataEnd: data_end(body, start); break;
      default: break;  // index records, statistics, summary offsets and unknown opcodes
    }
  }

  // Braced initializers evaluate left to right, so fields are read in record order.
  void header(Cursor& body) {
    if (header_seen_) return;
    header_seen_ = true;
    contents_.profile = body.string();
    contents_.library = body.string();
  }

  void schema(Cursor& body) {
    Schema schema{body.get<std::uint16_t>(), body.string(), body.string(),
                  body.bytes(body.get<std::uint32_t>())};
    if (schema.id != 0) contents_.schemas[schema.id] = std::move(schema);  // 0 is invalid
  }

  void channel(Cursor& body) {
    Channel channel{body.get<std::uint16_t>(), body.get<std::uint16_t>(), body.string(),
                    body.string(), read_string_map(body)};
    contents_.channels[channel.id] = std::move(channel);
  }

  void message(Cursor& body) {
    Message message{body.get<std::uint16_t>(), body.get<std::uint32_t>(),
                    body.get<std::uint64_t>(), body.get<std::uint64_t>(), {}};
    const std::uint64_t size = body.remaining();
    const char* data = body.take(size);
    message.data.assign(data, data + size);
    contents_.messages.push_back(std::move(message));
  }

  void chunk(Cursor& body, std::uint64_t start) {
    body.get<std::uint64_t>();  // message_start_time
    body.get<std::uint64_t>();  // message_end_time
    const auto uncompressed_size = body.get<std::uint64_t>();
    const auto crc = body.get<std::uint32_t>();
    const std::string compression = body.string();
    Cursor inner = body.sub(body.get<std::uint64_t>());
    if (!compression.empty()) {
      throw ParseError{start, "unsupported chunk compression \"" + compression +
                                  "\" (only uncompressed chunks can be read)"};
    }
    if (inner.remaining() != uncompressed_size) {
      throw ParseError{start, "chunk uncompressed_size " + std::to_string(uncompressed_size) +
                                  " differs from its " + std::to_string(inner.remaining()) +
                                  " record bytes"};
    }
    check_crc(crc, crc_of(file_, inner.pos(), inner.pos() + uncompressed_size), start, "chunk");
    records(inner, true);
  }

  void attachment(Cursor& body, std::uint64_t start) {
    const std::uint64_t crc_begin = body.pos();
    Attachment attachment{body.get<std::uint64_t>(), body.get<std::uint64_t>(), body.string(),
                          body.string(), body.bytes(body.get<std::uint64_t>())};
    const std::uint32_t computed = crc_of(file_, crc_begin, body.pos());
    check_crc(body.get<std::uint32_t>(), computed, start,
              "attachment \"" + attachment.name + "\"");
    contents_.attachments.push_back(std::move(attachment));
  }

  void metadata(Cursor& body) {
    Metadata metadata{body.string(), read_string_map(body)};
    contents_.metadata.push_back(std::move(metadata));
  }

  void data_end(Cursor& body, std::uint64_t start) {
    check_crc(body.get<std::uint32_t>(), crc_of(file_, 0, start), start, "data section");
  }

  void footer(Cursor& body, std::uint64_t start) {
    const auto summary_start = body.get<std::uint64_t>();
    body.get<std::uint64_t>();  // summary_offset_start
    const auto crc = body.get<std::uint32_t>();
    footer_seen_ = true;
    if (crc == 0) return;
    const std::uint64_t from = summary_start == 0 ? start : summary_start;
    if (from > start) {
      throw ParseError{start, "Footer summary_start " + std::to_string(summary_start) +
                                  " points past the Footer"};
    }
    // The CRC covers the summary up to and including the Footer's summary_offset_start.
    check_crc(crc, crc_of(file_, from, start + kRecordPrefix + 16), from, "summary");
  }

  const std::string& file_;
  Contents contents_;
  bool header_seen_ = false;
  bool footer_seen_ = false;
};

bool load(const std::string& path, std::string* bytes) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) return false;
  const std::streamoff size = in.tellg();
  if (size < 0) return false;
  bytes->resize(static_cast<std::size_t>(size));
  in.seekg(0);
  return static_cast<bool>(in.read(bytes->data(), size));
}

}  // namespace

// ---- Writer --------------------------------------------------------------------------------

Writer::~Writer() {
  if (out_.is_open()) close();
}

bool Writer::open(const std::string& path, const std::string& profile,
                  const std::string& library) {
  if (out_.is_open()) close();
  data_crc_ = 0;
  position_ = 0;
  schemas_.clear();
  channels_.clear();
  channel_message_counts_.clear();
  attachment_index_.clear();
  metadata_index_.clear();
  message_count_ = message_start_time_ = message_end_time_ = 0;
  error_.clear();
  path_ = path;
  out_.open(path, std::ios::binary | std::ios::trunc);
  if (!out_.is_open()) {
    error_ = path + ": cannot create file";
    return false;
  }
  out_.write(kMagic, kMagicSize);
  data_crc_ = crc_update(0, kMagic, kMagicSize);
  position_ = kMagicSize;
  write_record(kHeader, body_of(profile, library), true);
  return true;
}

void Writer::write_record(std::uint8_t opcode, const std::string& body, bool data_section) {
  const std::string bytes = record_bytes(opcode, body);
  out_.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  if (data_section) data_crc_ = crc_update(data_crc_, bytes.data(), bytes.size());
  position_ += bytes.size();
}

void Writer::add_schema(const Schema& schema) {
  if (!out_.is_open()) return;
  write_record(kSchema, schema_body(schema), true);
  const auto same_id = [&schema](const Schema& s) { return s.id == schema.id; };
  if (std::none_of(schemas_.begin(), schemas_.end(), same_id)) schemas_.push_back(schema);
}

void Writer::add_channel(const Channel& channel) {
  if (!out_.is_open()) return;
  write_record(kChannel, channel_body(channel), true);
  const auto same_id = [&channel](const Channel& c) { return c.id == channel.id; };
  if (std::none_of(channels_.begin(), channels_.end(), same_id)) channels_.push_back(channel);
}

void Writer::write(const Message& message) {
  if (!out_.is_open()) return;
  std::string body = body_of(message.channel_id, message.sequence, message.log_time_ns,
                             message.publish_time_ns);
  body.append(message.data.begin(), message.data.end());
  write_record(kMessage, body, true);
  const std::uint64_t t = message.log_time_ns;
  message_start_time_ = message_count_ == 0 ? t : std::min(message_start_time_, t);
  message_end_time_ = message_count_ == 0 ? t : std::max(message_end_time_, t);
  ++message_count_;
  ++channel_message_counts_[message.channel_id];
}

void Writer::add_attachment(const Attachment& attachment) {
  if (!out_.is_open()) return;
  const std::uint64_t size = attachment.data.size();
  std::string body = body_of(attachment.log_time_ns, attachment.create_time_ns, attachment.name,
                             attachment.media_type, size) + attachment.data;
  put<std::uint32_t>(body, crc_update(0, body.data(), body.size()));
  attachment_index_.push_back({position_, kRecordPrefix + body.size(), attachment.log_time_ns,
                               attachment.create_time_ns, size,
                               attachment.name, attachment.media_type});
  write_record(kAttachment, body, true);
}

void Writer::add_metadata(const Metadata& metadata) {
  if (!out_.is_open()) return;
  const std::string body = body_of(metadata.name, metadata.entries);
  metadata_index_.push_back({position_, kRecordPrefix + body.size(), metadata.name});
  write_record(kMetadata, body, true);
}

std::string Writer::statistics_body() const {
  const auto count32 = [](std::size_t n) { return static_cast<std::uint32_t>(n); };
  const std::uint32_t chunk_count = 0;  // this writer never chunks
  return body_of(message_count_, static_cast<std::uint16_t>(schemas_.size()),
                 count32(channels_.size()), count32(attachment_index_.size()),
                 count32(metadata_index_.size()), chunk_count, message_start_time_,
                 message_end_time_, channel_message_counts_);
}

std::string Writer::summary_and_footer(std::uint64_t summary_start) const {
  std::string schemas, channels, attachments, metadata;
  for (const Schema& s : schemas_) schemas += record_bytes(kSchema, schema_body(s));
  for (const Channel& c : channels_) channels += record_bytes(kChannel, channel_body(c));
  for (const AttachmentIndexEntry& a : attachment_index_) {
    attachments += record_bytes(kAttachmentIndex, body_of(a.offset, a.length, a.log_time_ns,
                                                          a.create_time_ns, a.data_size, a.name,
                                                          a.media_type));
  }
  for (const MetadataIndexEntry& m : metadata_index_) {
    metadata += record_bytes(kMetadataIndex, body_of(m.offset, m.length, m.name));
  }
  // Each non-empty group of same-opcode records gets a Summary Offset record.
  std::string out, offsets;
  const auto add_group = [&](std::uint8_t opcode, const std::string& records) {
    const std::uint64_t group_start = summary_start + out.size(), group_length = records.size();
    if (group_length == 0) return;
    offsets += record_bytes(kSummaryOffset, body_of(opcode, group_start, group_length));
    out += records;
  };
  add_group(kSchema, schemas);
  add_group(kChannel, channels);
  add_group(kStatistics, record_bytes(kStatistics, statistics_body()));
  add_group(kAttachmentIndex, attachments);
  add_group(kMetadataIndex, metadata);
  const std::uint64_t summary_offset_start = summary_start + out.size();
  out += offsets;
  put<std::uint8_t>(out, kFooter);
  put<std::uint64_t>(out, 20);  // summary_start, summary_offset_start, summary_crc
  put<std::uint64_t>(out, summary_start);
  put<std::uint64_t>(out, summary_offset_start);
  put<std::uint32_t>(out, crc_update(0, out.data(), out.size()));  // CRC of all of `out` so far
  out.append(kMagic, kMagicSize);
  return out;
}

bool Writer::close() {
  if (!out_.is_open()) {
    error_ = "close(): no file is open";
    return false;
  }
  write_record(kDataEnd, body_of(data_crc_), false);
  const std::string tail = summary_and_footer(position_);
  out_.write(tail.data(), static_cast<std::streamsize>(tail.size()));
  position_ += tail.size();
  out_.close();
  if (out_.fail()) {
    error_ = path_ + ": write error";
    return false;
  }
  return true;
}

// ---- Reader --------------------------------------------------------------------------------

std::optional<Contents> read_file(const std::string& path, std::string* error) {
  std::string file;
  if (!load(path, &file)) {
    if (error) *error = path + ": cannot open file for reading";
    return std::nullopt;
  }
  try {
    return FileParser(file).parse();
  } catch (const ParseError& e) {
    if (error) *error = path + ": " + e.message + " at offset " + std::to_string(e.offset);
    return std::nullopt;
  }
}

}  // namespace entourage::mcap
