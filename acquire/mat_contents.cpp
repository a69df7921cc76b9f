#include "acquire/mat_contents.hpp"

#include <hdf5.h>
#include <matio.h>
#include <zlib.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <new>
#include <sstream>

#include "acquire/csv_units.hpp"
#include "common/error.hpp"

namespace fourbar {

namespace {

struct MatFile {
  mat_t* mat = nullptr;
  ~MatFile() {
    if (mat) Mat_Close(mat);
  }
};

struct VarDeleter {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using Var = std::unique_ptr<matvar_t, VarDeleter>;

const char* class_name(matio_classes c) {
  switch (c) {
    case MAT_C_DOUBLE: return "DOUBLE";
    case MAT_C_SINGLE: return "SINGLE";
    case MAT_C_INT8: return "INT8";
    case MAT_C_UINT8: return "UINT8";
    case MAT_C_INT16: return "INT16";
    case MAT_C_UINT16: return "UINT16";
    case MAT_C_INT32: return "INT32";
    case MAT_C_UINT32: return "UINT32";
    case MAT_C_INT64: return "INT64";
    case MAT_C_UINT64: return "UINT64";
    default: return nullptr;  // char, struct, cell, sparse, function, object
  }
}

template <class T>
double at(const void* data, std::size_t i) {
  return static_cast<double>(static_cast<const T*>(data)[i]);
}

double element(const matvar_t& v, std::size_t i) {
  switch (v.class_type) {
    case MAT_C_DOUBLE: return at<double>(v.data, i);
    case MAT_C_SINGLE: return at<float>(v.data, i);
    case MAT_C_INT8: return at<std::int8_t>(v.data, i);
    case MAT_C_UINT8: return at<std::uint8_t>(v.data, i);
    case MAT_C_INT16: return at<std::int16_t>(v.data, i);
    case MAT_C_UINT16: return at<std::uint16_t>(v.data, i);
    case MAT_C_INT32: return at<std::int32_t>(v.data, i);
    case MAT_C_UINT32: return at<std::uint32_t>(v.data, i);
    case MAT_C_INT64: return at<std::int64_t>(v.data, i);
    case MAT_C_UINT64: return at<std::uint64_t>(v.data, i);
    default: return 0;
  }
}

/// Seconds per unit of a time variable's name, 0 when it is not one.
double time_variable_unit_s(std::string name) {
  std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
  if (name == "t" || name == "time" || name == "time_s") return 1.0;
  if (name == "time_ms" || name == "t_ms") return 1e-3;
  return 0.0;
}

bool is_rate_name(const std::string& name) {
  static const char* kNames[] = {"fs", "Fs", "FS", "sample_rate", "sample_rate_hz", "samplerate", "SampleRate", "rate"};
  return std::any_of(std::begin(kNames), std::end(kNames), [&](const char* n) { return name == n; });
}

/// The sub-elements of the miMATRIX element whose data are bytes [at, end):
/// empty when each lies within it (nested miMATRIX elements of cell and
/// struct arrays too), else where one does not. libmatio trusts these
/// sizes: a dimensions sub-element claiming 1.9 GB inside an 816-byte
/// variable made it allocate 3.9 GB (fuzzing: tests/fuzz/regressions/mat/).
std::string v5_matrix_damage(const std::function<std::uint32_t(std::size_t)>& u32, std::size_t at, std::size_t end,
                             int depth) {
  if (depth > 16) return "damaged: variables nested more than 16 deep at byte " + std::to_string(at);
  while (at < end) {
    if (end - at < 8) return "damaged: a variable's last part at byte " + std::to_string(at) + " is cut short";
    const std::uint32_t type = u32(at);
    if (type >> 16) {  // small data element: 2-byte size, 2-byte type, 4 bytes of data
      if ((type >> 16) > 4) return "damaged: a small data element at byte " + std::to_string(at) + " claims more than 4 bytes";
      at += 8;
      continue;
    }
    const std::size_t count = u32(at + 4);
    if (count > end - at - 8)
      return "damaged: a part of a variable at byte " + std::to_string(at) + " claims " + std::to_string(count) +
             " bytes, more than the variable holds";
    if (type == 14)
      if (std::string d = v5_matrix_damage(u32, at + 8, at + 8 + count, depth + 1); !d.empty()) return d;
    at = std::min(end, at + 8 + (count + 7) / 8 * 8);
  }
  return {};
}


/// The largest dimensions or name part a variable's header may claim (a
/// MATLAB name has at most 63 characters; 4096 bytes are 1024 dimensions).
constexpr std::size_t kMaxHeaderPart = 4096;

/// A compressed variable (miCOMPRESSED, data bytes [data, data + size)):
/// libmatio inflates its header and trusts the sizes there as it does in an
/// uncompressed one (a name claiming 1.9 GB in a 58-byte variable cost 9 s
/// and gigabytes; fuzzing: tests/fuzz/regressions/mat/). Inflates only the
/// header (array flags, dimensions, name tags); empty when they are sound.
std::string v5_compressed_damage(const unsigned char* data, std::size_t size, bool swap, std::size_t at) {
  const std::string where = "damaged: the compressed variable at byte " + std::to_string(at);
  std::vector<unsigned char> head(8 + 3 * (8 + kMaxHeaderPart));
  z_stream z{};
  if (inflateInit(&z) != Z_OK) throw std::bad_alloc();
  z.next_in = const_cast<unsigned char*>(data);
  z.avail_in = static_cast<uInt>(size);
  z.next_out = head.data();
  z.avail_out = static_cast<uInt>(head.size());
  const int rc = inflate(&z, Z_SYNC_FLUSH);
  head.resize(head.size() - z.avail_out);
  inflateEnd(&z);
  if (rc != Z_OK && rc != Z_STREAM_END && rc != Z_BUF_ERROR) return where + " does not inflate";
  auto u32 = [&](std::size_t i) {
    std::uint32_t v = 0;
    std::memcpy(&v, &head[i], 4);
    return swap ? __builtin_bswap32(v) : v;
  };
  if (head.size() < 8 || u32(0) != 14) return where + " holds no variable";
  const std::size_t end = 8 + static_cast<std::size_t>(u32(4));
  std::size_t i = 8;
  for (int part = 0; part < 3; ++part) {  // array flags, dimensions, name
    if (i + 8 > head.size() || i + 8 > end) return where + " ends within its header";
    const std::uint32_t type = u32(i);
    if (type >> 16) {
      i += 8;
      continue;
    }
    const std::size_t count = u32(i + 4);
    if (count > kMaxHeaderPart || count > end - i - 8)
      return where + " has a header part claiming " + std::to_string(count) + " bytes";
    i += 8 + (count + 7) / 8 * 8;
  }
  return {};
}

/// v5 files: checks the endian indicator and walks the top-level data
/// elements (tag: type, byte count), the parts of uncompressed variables
/// and the headers of compressed ones; empty when sound, else what is wrong.
/// libmatio stops quietly at a truncated element, which would drop the
/// variables after it.
std::string v5_damage(const std::filesystem::path& file) {
  const std::string truncated = "truncated: a variable runs past the end of the file (an interrupted copy?)";
  std::ifstream in(file, std::ios::binary);
  std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (bytes.size() < 128) return truncated;
  // The endian indicator must read "IM" (this machine's byte order) or "MI";
  // with anything else libmatio guesses, and a size read in the wrong order
  // asked it for 8 GB (fuzzing: tests/fuzz/regressions/mat/).
  if (!((bytes[126] == 'I' && bytes[127] == 'M') || (bytes[126] == 'M' && bytes[127] == 'I')))
    return "damaged header: the byte-order mark at bytes 126-127 is not 'IM' or 'MI'";
  const bool swap = bytes[126] == 'M' && bytes[127] == 'I';
  auto u32 = [&](std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, &bytes[at], 4);
    return swap ? __builtin_bswap32(v) : v;
  };
  std::size_t at = 128;
  while (at < bytes.size()) {
    if (at + 8 > bytes.size()) return truncated;
    const std::uint32_t type = u32(at), count = u32(at + 4);
    // A file's top level holds variables only: miMATRIX (14) or miCOMPRESSED (15).
    if (type != 14 && type != 15)
      return "damaged: the data element at byte " + std::to_string(at) + " is of type " + std::to_string(type) +
             ", not a variable (miMATRIX or miCOMPRESSED)";
    const std::size_t end = at + 8 + static_cast<std::size_t>(count);
    if (end > bytes.size()) return truncated;
    if (type == 14)
      if (std::string d = v5_matrix_damage(u32, at + 8, end, 0); !d.empty()) return d;
    if (type == 15)
      if (std::string d = v5_compressed_damage(&bytes[at + 8], count, swap, at); !d.empty()) return d;
    at = type == 15 ? end : (end + 7) / 8 * 8;  // miMATRIX is padded to 8 bytes, miCOMPRESSED is not
  }
  return {};
}

struct VarInfo {
  std::string name;                ///< as UTF-8 (Latin-1 read as such)
  std::string raw;                 ///< as stored, for libmatio
  const char* cls = nullptr;  ///< null: not a real numeric array
  std::size_t rows = 0, cols = 0;
  bool numeric() const { return cls != nullptr; }
  std::size_t length() const { return std::max(rows, cols); }
  std::size_t width() const { return std::min(rows, cols); }
};

/// Reads the whole file in its constructor; take() hands the result over.
class MatLoader {
 public:
  MatLoader(const std::filesystem::path& file, const ReaderOptions& options) {
    info_.file = file;
    const std::string f = file.string();
    Mat_LogInitFunc("fourbar", [](int, char*) {});  // nor libmatio its warnings
    // v4 (MATLAB before 1996) has no header to check a file against, and
    // libmatio spends seconds and gigabytes on a damaged one (fuzzing) —
    // already in Mat_Open, which tries v4 when the v5/v7.3 header is missing
    // (a 120-byte file whose "name length" read 690 MB: 7 s). So the header
    // is checked first.
    const std::string v4 = f + ": a MATLAB v4 file (or not a MATLAB file at all): not read; save it from MATLAB as "
                               "v7 (save -v7) or v7.3";
    const unsigned header = mat_header_version(file);
    if (header == 0) throw InputError(v4);
    // HDF5 prints no error stacks: the errors below say it. Only for v7.3, so
    // that reading a v5 file leaves libhdf5 untouched (uninitialised) in
    // this process, and a child forked for a v7.3 file starts it afresh.
    if (header == 0x0200) H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
    MatFile m;
    m.mat = Mat_Open(f.c_str(), MAT_ACC_RDONLY);
    if (!m.mat) throw InputError(f + ": not a readable MATLAB file (damaged or not a .mat); re-export it from MATLAB");
    const mat_ft version = Mat_GetVersion(m.mat);
    if (version == MAT_FT_MAT4) throw InputError(v4);
    if ((version == MAT_FT_MAT73) != (header == 0x0200))
      throw InputError(f + ": damaged header: libmatio reads it as another MATLAB version than its bytes 124-127 "
                           "say; re-export it from MATLAB");
    info_.format = version == MAT_FT_MAT73 ? "MAT v7.3" : "MAT v5";
    std::error_code ec;
    const auto file_bytes = std::filesystem::file_size(file, ec);
    if (version == MAT_FT_MAT5)
      if (const std::string damage = v5_damage(file); !damage.empty())
        throw InputError(f + ": " + damage + " (" + std::to_string(file_bytes) + " bytes); copy the file again");

    // Every variable's header (class and size), without its data.
    std::vector<VarInfo> vars;
    while (Var v{Mat_VarReadNextInfo(m.mat)}) {
      VarInfo vi;
      vi.raw = v->name ? v->name : "";
      vi.name = as_utf8(vi.raw);  // names go into TOML manifests
      if (v->rank == 2 && !v->isComplex && v->class_type != MAT_C_SPARSE) {
        vi.cls = class_name(v->class_type);
        vi.rows = v->dims[0], vi.cols = v->dims[1];
      }
      if (vi.name.empty()) continue;
      if (!vi.numeric()) {
        info_.notes.push_back("variable '" + vi.name + "' is not a real numeric matrix; not a channel");
        continue;
      }
      // A size the file cannot hold even compressed (zlib: at most ~1032:1)
      // is damage, not a recording.
      const double bytes = static_cast<double>(vi.rows) * static_cast<double>(vi.cols) * 8.0;
      if (bytes > 1100.0 * static_cast<double>(file_bytes) + 4096.0)
        throw InputError(f + ": variable '" + vi.name + "' claims " + std::to_string(vi.rows) + "x" +
                         std::to_string(vi.cols) + " values, more than the file can hold (a damaged file)");
      vars.push_back(vi);
    }
    if (vars.empty() && info_.notes.empty())
      throw InputError(f + ": no variable could be read (an empty or damaged " + info_.format + " file); re-export it");
    std::size_t length = 0;
    for (const auto& v : vars) length = std::max(length, v.length());
    if (length < 2)
      throw InputError(f + ": no numeric variable with more than one value; a recording needs its channels as "
                       "vectors or matrix columns" + list_variables(vars));

    // Sample rate source (see the header).
    std::optional<double> rate = options.sample_rate_hz;
    if (options.rate_variable) {
      const auto it = std::find_if(vars.begin(), vars.end(), [&](const VarInfo& v) { return v.name == *options.rate_variable; });
      if (it == vars.end())
        throw InputError(f + ": the manifest's rate_variable '" + *options.rate_variable +
                         "' is not a numeric variable in this file" + list_variables(vars) +
                         "; name the variable that holds the rate, or give sample_rate_hz instead");
      if (it->rows * it->cols != 1)
        throw InputError(f + ": rate_variable '" + it->name + "' is " + std::to_string(it->rows) + "x" +
                         std::to_string(it->cols) + ", not a scalar; name the scalar that holds the rate in Hz");
      rate = read_scalar(m.mat, it->raw, f);
      info_.rate_variable = it->name;
    }

    int time_var = -1;
    for (std::size_t i = 0; i < vars.size(); ++i) {
      const VarInfo& v = vars[i];
      if (v.length() != length) {
        if (v.length() > 1) info_.notes.push_back("variable '" + v.name + "' (" + std::to_string(v.rows) + "x" +
                                                  std::to_string(v.cols) + ") has another length; not a channel");
        continue;
      }
      if (v.width() == 1 && time_var < 0 && time_variable_unit_s(v.name) > 0) {
        time_var = static_cast<int>(i);
        continue;
      }
      add_channels(m.mat, v, f);
    }
    if (columns_.empty()) throw InputError(f + ": only a time variable; the recording needs channels" + list_variables(vars));

    if (!rate && time_var >= 0) {
      const VarInfo& tv = vars[static_cast<std::size_t>(time_var)];
      rate = rate_from_time(m.mat, tv, f);
    }
    if (!rate) {
      for (const auto& v : vars)
        if (v.rows * v.cols == 1 && is_rate_name(v.name)) {
          rate = read_scalar(m.mat, v.raw, f);
          info_.rate_variable = v.name;
          break;
        }
    }
    if (!rate)
      throw InputError(f + ": no sample rate: no time variable (t, time, time_s) and no rate scalar (fs, sample_rate, …)" +
                       list_variables(vars) + "; set rate_variable (or sample_rate_hz) in the manifest");
    if (!(*rate >= 1e-3 && *rate <= 1e9))
      throw InputError(f + ": sample rate " + std::to_string(*rate) + " Hz" +
                       (info_.rate_variable ? " (variable '" + *info_.rate_variable + "')" : std::string()) +
                       " is not between 0.001 Hz and 1 GHz; check the rate variable or give sample_rate_hz");
    info_.sample_rate_hz = *rate;
    info_.frames = length;
    info_.channels = static_cast<int>(columns_.size());
    std::string cls;
    for (const auto& v : vars)
      if (v.length() == length && static_cast<int>(&v - vars.data()) != time_var)
        cls = cls.empty() || cls == v.cls ? v.cls : "MIXED";
    info_.sample_format = cls;
  }

  MatContents take() && { return {std::move(info_), std::move(columns_)}; }

 private:
  static std::string list_variables(const std::vector<VarInfo>& vars) {
    std::string s = " (variables found:";
    for (const auto& v : vars) s += " " + v.name + " " + std::to_string(v.rows) + "x" + std::to_string(v.cols) + ",";
    if (vars.empty()) s += " none,";
    s.back() = ')';
    return s;
  }

  static Var read_var(mat_t* mat, const std::string& name, const std::string& f) {
    Var v{Mat_VarRead(mat, name.c_str())};
    if (!v || !v->data || !class_name(v->class_type))
      throw InputError(f + ": cannot read the data of variable '" + name + "' (a damaged file); re-export it");
    return v;
  }

  static double read_scalar(mat_t* mat, const std::string& name, const std::string& f) {
    const Var v = read_var(mat, name, f);
    return element(*v, 0);
  }

  void add_channels(mat_t* mat, const VarInfo& vi, const std::string& f) {
    const Var v = read_var(mat, vi.raw, f);
    if (v->rank != 2 || v->dims[0] != vi.rows || v->dims[1] != vi.cols)
      throw InputError(f + ": variable '" + vi.name + "' changed size between its header and its data (a damaged file)");
    const bool by_column = vi.rows >= vi.cols;  // the longer dimension is time
    const std::size_t n = vi.length(), width = vi.width();
    for (std::size_t c = 0; c < width; ++c) {
      std::vector<double> col(n);
      for (std::size_t i = 0; i < n; ++i) {
        const double x = element(*v, by_column ? c * vi.rows + i : i * vi.rows + c);
        if (!std::isfinite(x))
          throw InputError(f + ": variable '" + vi.name + "' element " + std::to_string(i + 1) +
                           (width > 1 ? " of " + std::string(by_column ? "column " : "row ") + std::to_string(c + 1) : "") +
                           " is not a finite number; every sample must be a number (fix or cut it)");
        col[i] = x;
      }
      columns_.push_back(std::move(col));
      if (width == 1) info_.channel_names.push_back(vi.name);
      else info_.channel_names.push_back(vi.name + (by_column ? "(:," + std::to_string(c + 1) + ")"
                                                              : "(" + std::to_string(c + 1) + ",:)"));
    }
  }

  double rate_from_time(mat_t* mat, const VarInfo& tv, const std::string& f) {
    const Var v = read_var(mat, tv.raw, f);
    const double unit = time_variable_unit_s(tv.name);
    const std::size_t n = tv.length();
    const double t0 = element(*v, 0) * unit, tn = element(*v, n - 1) * unit;
    if (!(tn > t0) || !std::isfinite(tn - t0))
      throw InputError(f + ": the time variable '" + tv.name + "' does not increase; fix it or set sample_rate_hz");
    const double rate = static_cast<double>(n - 1) / (tn - t0);
    for (std::size_t i = 0; i < n; ++i) {
      const double t = element(*v, i) * unit, expected = t0 + static_cast<double>(i) / rate;
      if (!(std::abs(t - expected) <= 0.5 / rate)) {
        std::ostringstream os;
        os.precision(10);
        os << f << ": time variable '" << tv.name << "' element " << i + 1 << " = " << t << " s is not uniform: sampling at "
           << rate << " Hz puts it at " << expected << " s; acquire needs uniformly sampled data (or set sample_rate_hz)";
        throw InputError(os.str());
      }
    }
    info_.start_time_s = t0;
    return rate;
  }

  RecordingInfo info_;
  std::vector<std::vector<double>> columns_;
};

}  // namespace

MatContents read_mat_contents(const std::filesystem::path& file, const ReaderOptions& options) {
  return MatLoader(file, options).take();
}

}  // namespace fourbar
