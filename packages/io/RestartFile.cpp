#include "io/RestartFile.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "common/Error.hpp"

namespace contessa::io {

namespace {

constexpr char kMagic[16] = {'C', 'O', 'N', 'T', 'E', 'S', 'S', 'A', ' ', 'R', 'E', 'S', 'T', 'A', 'R', 'T'};

template <class T>
void put(std::string& out, const T& value) {
  out.append(reinterpret_cast<const char*>(&value), sizeof value);
}

// Reads from the payload; running past its end means a corrupt file (the checksum matched, so a defect of
// the writer, or a file from another program).
class Reader {
 public:
  Reader(const std::string& bytes, std::size_t offset, const std::string& path) : bytes_(bytes), at_(offset), path_(path) {}
  template <class T>
  T get() {
    T value;
    need(sizeof value);
    std::memcpy(&value, bytes_.data() + at_, sizeof value);
    at_ += sizeof value;
    return value;
  }
  std::string text(std::uint64_t n) {
    need(n);
    std::string s = bytes_.substr(at_, n);
    at_ += n;
    return s;
  }
  void doubles(std::uint64_t n, std::vector<double>& out) {
    need(n * sizeof(double));
    out.resize(n);
    if (n > 0) std::memcpy(out.data(), bytes_.data() + at_, n * sizeof(double));
    at_ += n * sizeof(double);
  }
  bool atEnd() const { return at_ == bytes_.size(); }

 private:
  void need(std::uint64_t n) const {
    if (n > bytes_.size() - at_) throw InputError("--restart " + path_ + ": corrupt restart file (a record runs past its end)");
  }
  const std::string& bytes_;
  std::size_t at_;
  const std::string& path_;
};

// "path = value" lines into a map (the deck text of restartDeckText).
std::map<std::string, std::string> deckEntries(const std::string& text, std::vector<std::string>& order) {
  std::map<std::string, std::string> out;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    const auto eq = line.find(" = ");
    const std::string key = eq == std::string::npos ? line : line.substr(0, eq);
    if (out.emplace(key, eq == std::string::npos ? "" : line.substr(eq + 3)).second) order.push_back(key);
  }
  return out;
}

}  // namespace

std::uint64_t fnv1a(const void* data, std::size_t bytes, std::uint64_t hash) {
  const auto* p = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < bytes; ++i) {
    hash ^= p[i];
    hash *= 1099511628211ULL;
  }
  return hash;
}

std::string encodeRestart(RestartContent content) {
  std::sort(content.records.begin(), content.records.end(), [](const RestartRecord& a, const RestartRecord& b) {
    return a.kind != b.kind ? a.kind < b.kind : a.id < b.id;
  });
  std::string payload;
  put(payload, static_cast<std::uint64_t>(content.deck.size()));
  payload += content.deck;
  put(payload, content.nodes);
  put(payload, content.elements);
  put(payload, content.meshHash);
  put(payload, static_cast<std::uint64_t>(content.records.size()));
  for (const auto& r : content.records) {
    put(payload, r.kind);
    put(payload, r.id);
    put(payload, static_cast<std::uint64_t>(r.values.size()));
    payload.append(reinterpret_cast<const char*>(r.values.data()), r.values.size() * sizeof(double));
  }
  std::string out(kMagic, sizeof kMagic);
  put(out, kRestartFormatVersion);
  put(out, static_cast<std::uint64_t>(payload.size()));
  put(out, fnv1a(payload.data(), payload.size()));
  return out + payload;
}

RestartContent decodeRestart(const std::string& bytes, const std::string& path) {
  const std::string where = "--restart " + path + ": ";
  constexpr std::size_t header = sizeof kMagic + sizeof(std::uint32_t) + 2 * sizeof(std::uint64_t);
  requireInput(bytes.size() >= sizeof kMagic && std::memcmp(bytes.data(), kMagic, sizeof kMagic) == 0,
               where + "not a Contessa restart file");
  requireInput(bytes.size() >= header, where + "truncated restart file (" + std::to_string(bytes.size()) + " bytes)");
  Reader head(bytes, sizeof kMagic, path);
  const auto version = head.get<std::uint32_t>();
  requireInput(version == kRestartFormatVersion, where + "restart file format version " + std::to_string(version) +
                                                     ", this Contessa reads version " +
                                                     std::to_string(kRestartFormatVersion));
  const auto payloadBytes = head.get<std::uint64_t>();
  const auto checksum = head.get<std::uint64_t>();
  requireInput(bytes.size() - header >= payloadBytes, where + "truncated restart file (" + std::to_string(bytes.size()) +
                                                          " bytes, " + std::to_string(header + payloadBytes) +
                                                          " expected)");
  requireInput(bytes.size() - header == payloadBytes, where + "corrupt restart file (" +
                                                          std::to_string(bytes.size() - header - payloadBytes) +
                                                          " bytes past its end)");
  requireInput(fnv1a(bytes.data() + header, payloadBytes) == checksum,
               where + "corrupt restart file (checksum mismatch)");
  Reader in(bytes, header, path);
  RestartContent c;
  c.deck = in.text(in.get<std::uint64_t>());
  c.nodes = in.get<std::int64_t>();
  c.elements = in.get<std::int64_t>();
  c.meshHash = in.get<std::uint64_t>();
  const auto count = in.get<std::uint64_t>();
  requireInput(count <= payloadBytes / (3 * sizeof(std::int64_t)), where + "corrupt restart file (record count)");
  c.records.resize(count);
  for (auto& r : c.records) {
    r.kind = in.get<std::int64_t>();
    r.id = in.get<std::int64_t>();
    in.doubles(in.get<std::uint64_t>(), r.values);
  }
  requireInput(in.atEnd(), where + "corrupt restart file (bytes after the last record)");
  return c;
}

RestartContent readRestartFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  requireInput(static_cast<bool>(in), "--restart " + path + ": cannot open the restart file (" +
                                          std::string(std::strerror(errno)) + ")");
  std::ostringstream bytes;
  bytes << in.rdbuf();
  return decodeRestart(bytes.str(), path);
}

std::string writeFileAtomically(const std::string& path, const std::string& bytes) {
  const std::string temporary = path + ".tmp";
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) return temporary + ": " + std::strerror(errno);
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      // write() returning 0 sets no errno.
      const std::string reason = n == 0 ? std::string("short write (the disk accepted no more bytes)") : std::strerror(errno);
      ::close(fd);
      ::unlink(temporary.c_str());
      return temporary + ": " + reason;
    }
    done += static_cast<std::size_t>(n);
  }
  // On disk before the rename makes it the restart file: a crash leaves the old file or the new one.
  const bool synced = ::fsync(fd) == 0;
  const int syncError = errno;
  const bool closed = ::close(fd) == 0;  // always closed, even when fsync failed
  if (!synced || !closed) {
    const std::string reason = std::strerror(synced ? errno : syncError);
    ::unlink(temporary.c_str());
    return temporary + ": " + reason;
  }
  if (::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    ::unlink(temporary.c_str());
    return path + ": " + reason;
  }
  // The rename itself is on disk once the directory is: without this a power loss may bring back the old
  // file (never a torn one). A directory that cannot be opened or synced leaves that weaker guarantee.
  const std::string::size_type slash = path.find_last_of('/');
  const std::string directory = slash == std::string::npos ? std::string(".") : path.substr(0, slash == 0 ? 1 : slash);
  const int dir = ::open(directory.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
  if (dir >= 0) {
    ::fsync(dir);
    ::close(dir);
  }
  return "";
}

std::string deckDifference(const std::string& saved, const std::string& current) {
  if (saved == current) return "";
  std::vector<std::string> savedOrder, currentOrder;
  const auto a = deckEntries(saved, savedOrder), b = deckEntries(current, currentOrder);
  for (const auto& key : currentOrder) {
    const auto it = a.find(key);
    if (it == a.end()) return key + " is not in the restart file's deck (" + b.at(key) + " here)";
    if (it->second != b.at(key)) return key + " is " + it->second + " in the restart file, " + b.at(key) + " here";
  }
  for (const auto& key : savedOrder)
    if (b.find(key) == b.end()) return key + " (" + a.at(key) + ") is in the restart file's deck, not here";
  return "the order of the deck's parameters differs";
}

RestartRecords::RestartRecords(const std::vector<RestartRecord>& records) {
  for (const auto& r : records) index_[{r.kind, r.id}] = &r.values;
}

const std::vector<double>* RestartRecords::find(std::int64_t kind, std::int64_t id) const {
  const auto it = index_.find({kind, id});
  return it == index_.end() ? nullptr : it->second;
}

const std::vector<double>& RestartRecords::at(std::int64_t kind, std::int64_t id, const std::string& what) const {
  const auto* r = find(kind, id);
  if (r == nullptr) throw InputError("restart file: no record of " + what);
  return *r;
}

}  // namespace contessa::io
