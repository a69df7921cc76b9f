#include "common/build_id.hpp"

#include <elf.h>
#include <link.h>

#include <cstdint>
#include <cstring>

namespace fourbar {

namespace {

/// dl_iterate_phdr visits the main program first; read its PT_NOTE segments.
int read_main_program_note(dl_phdr_info* info, std::size_t, void* out) {
  auto& id = *static_cast<std::string*>(out);
  for (ElfW(Half) i = 0; i < info->dlpi_phnum; ++i) {
    const ElfW(Phdr)& ph = info->dlpi_phdr[i];
    if (ph.p_type != PT_NOTE) continue;
    const auto* p = reinterpret_cast<const unsigned char*>(info->dlpi_addr + ph.p_vaddr);
    const unsigned char* end = p + ph.p_memsz;
    auto align4 = [](std::size_t n) { return (n + 3) & ~std::size_t{3}; };
    while (p + sizeof(ElfW(Nhdr)) <= end) {
      ElfW(Nhdr) note;
      std::memcpy(&note, p, sizeof note);
      const unsigned char* name = p + sizeof note;
      const unsigned char* desc = name + align4(note.n_namesz);
      if (desc + note.n_descsz > end) break;
      if (note.n_type == NT_GNU_BUILD_ID && note.n_namesz == 4 && std::memcmp(name, "GNU", 4) == 0) {
        static const char* hex = "0123456789abcdef";
        for (ElfW(Word) k = 0; k < note.n_descsz; ++k) id += {hex[desc[k] >> 4], hex[desc[k] & 15]};
        return 1;
      }
      p = desc + align4(note.n_descsz);
    }
  }
  return 1;  // only the main program
}

}  // namespace

const std::string& build_id() {
  static const std::string id = [] {
    std::string s;
    dl_iterate_phdr(read_main_program_note, &s);
    return s;
  }();
  return id;
}

}  // namespace fourbar
