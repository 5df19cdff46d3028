#include "language/wordnet.h"

#include <cstdlib>
#include <cstring>
#include <charconv>
#include <map>
#include <mutex>

#include <spdlog/spdlog.h>
#include <wn.h>

#include "util/bounded_table.h"
#include "util/file.h"
#include "util/text.h"

namespace apprentice::language {
namespace {

// The C library's own buffers hold WORDBUF (256) bytes; longer strings are
// never passed in.
constexpr std::size_t kMaxLemmaBytes = 200;

// The library's global state, mirrored: whether wninit() succeeded and from
// which directory. This and the lock are the process's only WordNet state,
// kept as function-local statics because the C library's state is global.
// Every noun synset's offset, ascending, and its size (WordNet::class_size).
struct SynsetSizes {
  std::vector<SynsetOffset> offsets;
  std::vector<int> sizes;
};

struct Library {
  std::mutex mutex;
  bool open = false;
  // wninit() initialises only once per process (later calls return its
  // first status without reopening anything), so every later open, even
  // after a failure, must go through re_wninit().
  bool initialised = false;
  std::string directory;  // "" = the environment or the compiled default
  bool saw_environment = false;
  std::optional<std::string> environment;  // WNSEARCHDIR before we touched it
  // class_size's table, built once from the directory the library reads.
  bool sizes_built = false;
  SynsetSizes sizes;
  // The answers so far, from the directory the library reads (wordnet.h).
  // Each table is bounded (util/bounded_table.h): a page or a script can
  // send any number of distinct unknown words. WordNet has ~150k lemmas, so
  // real use seldom fills one.
  static constexpr std::size_t kAnswersPerTable = 100000;
  util::BoundedTable<std::string, std::vector<SynsetOffset>> senses{kAnswersPerTable};
  util::BoundedTable<SynsetOffset, std::optional<Synset>> synsets{kAnswersPerTable};
  // Verbs: their own tables, since data.verb's offsets are not data.noun's.
  util::BoundedTable<std::string, std::vector<SynsetOffset>> verb_senses{kAnswersPerTable};
  util::BoundedTable<SynsetOffset, std::optional<Synset>> verb_synsets{kAnswersPerTable};
  util::BoundedTable<std::pair<int, std::string>, std::vector<std::string>> base_forms{kAnswersPerTable};  // by part of speech
  util::BoundedTable<std::string, bool> verbs{kAnswersPerTable};
  util::BoundedTable<std::string, bool> known{kAnswersPerTable};

  void forget_answers() {
    sizes_built = false;
    sizes = SynsetSizes{};
    senses.clear();
    synsets.clear();
    verb_senses.clear();
    verb_synsets.clear();
    base_forms.clear();
    verbs.clear();
    known.clear();
  }
};

Library& library() {
  static Library instance;
  return instance;
}

// The library reports errors by calling display_message, which by default
// prints to stderr; we report them as values instead.
int quiet_message(char*) { return -1; }

// A mutable, NUL-terminated copy for the C API, spaces as underscores.
struct CString {
  char text[WORDBUF] = {};
  explicit CString(std::string_view s, bool underscores = true) {
    std::size_t n = std::min(s.size(), kMaxLemmaBytes);
    std::memcpy(text, s.data(), n);
    text[n] = '\0';
    if (underscores)
      for (std::size_t i = 0; i < n; ++i)
        if (text[i] == ' ') text[i] = '_';
  }
};

std::string from_wordnet(const char* word) {
  std::string out = to_lower(word ? word : "");
  for (char& c : out)
    if (c == '_') c = ' ';
  // Adjective markers such as "(a)" only occur in adjective synsets.
  if (auto paren = out.find('('); paren != std::string::npos) out.erase(paren);
  return out;
}

// "(a receptacle where waste can be discarded; \"she tossed ...\")" ->
// "a receptacle where waste can be discarded".
std::string definition_of(const char* defn) {
  std::string text = defn ? defn : "";
  if (!text.empty() && text.front() == '(') text.erase(0, 1);
  if (auto quote = text.find("; \""); quote != std::string::npos) text.erase(quote);
  while (!text.empty() && (text.back() == ')' || text.back() == ' ')) text.pop_back();
  return text;
}

bool usable(std::string_view s) {
  return !s.empty() && s.size() <= kMaxLemmaBytes && s.find('\0') == std::string_view::npos;
}

}  // namespace

Result<WordNet> WordNet::open(const std::optional<std::filesystem::path>& dictionary) {
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  std::string wanted = dictionary ? dictionary->string() : "";
  if (!lib.open || wanted != lib.directory) {
    display_message = quiet_message;
    // WNSEARCHDIR is how the C library is told where the database is; it is
    // read inside wninit(), under our lock. Without a dictionary, the
    // caller's environment (as it was before any override) applies.
    if (!lib.saw_environment) {
      if (const char* env = std::getenv("WNSEARCHDIR")) lib.environment = env;
      lib.saw_environment = true;
    }
    if (dictionary) {
      ::setenv("WNSEARCHDIR", wanted.c_str(), 1);
    } else if (lib.environment) {
      ::setenv("WNSEARCHDIR", lib.environment->c_str(), 1);
    } else {
      ::unsetenv("WNSEARCHDIR");
    }
    int status = lib.initialised ? re_wninit() : wninit();
    lib.initialised = true;
    if (status != 0) {
      lib.open = false;
      const char* env = std::getenv("WNSEARCHDIR");
      return make_error(ErrorCode::kUnavailable,
                        "cannot open the WordNet database in " +
                            (env ? std::string(env) : std::string("the library's default directory")));
    }
    lib.open = true;
    if (wanted != lib.directory) lib.forget_answers();
    lib.directory = wanted;
    spdlog::debug("wordnet: opened {}", wanted.empty() ? "the default database" : wanted);
  }
  return WordNet();
}

namespace {

// Base forms by morphstr for one part of speech, excluding the word itself.
std::vector<std::string> base_forms(std::string_view word, int part_of_speech) {
  std::vector<std::string> forms;
  if (!usable(word)) return forms;
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  if (!lib.open) return forms;
  auto key = std::make_pair(part_of_speech, std::string(word));
  if (const auto* kept = lib.base_forms.find(key)) return *kept;
  CString query(word);
  std::string self = from_wordnet(query.text);
  // morphstr iterates through static state: the first call takes the word,
  // later calls take NULL, until it returns NULL.
  for (char* form = morphstr(query.text, part_of_speech); form != nullptr;
       form = morphstr(nullptr, part_of_speech)) {
    std::string base = from_wordnet(form);
    if (base != self && std::find(forms.begin(), forms.end(), base) == forms.end()) forms.push_back(base);
  }
  lib.base_forms.remember(std::move(key), forms);
  return forms;
}

}  // namespace

std::vector<std::string> WordNet::noun_base_forms(std::string_view word) const { return base_forms(word, NOUN); }

std::vector<std::string> WordNet::verb_base_forms(std::string_view word) const { return base_forms(word, VERB); }

std::vector<std::string> WordNet::adjective_base_forms(std::string_view word) const { return base_forms(word, ADJ); }

namespace {

// The senses of an exact lemma under one part of speech, kept in `table`.
// Under no lock: takes it.
std::vector<SynsetOffset> senses_of(std::string_view lemma, int part_of_speech,
                                    util::BoundedTable<std::string, std::vector<SynsetOffset>> Library::*table) {
  if (!usable(lemma)) return {};
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  if (!lib.open) return {};
  std::string key = from_wordnet(CString(lemma).text);
  if (const auto* kept = (lib.*table).find(key)) return *kept;
  std::vector<SynsetOffset> offsets;
  CString query(key);
  if (IndexPtr index = index_lookup(query.text, part_of_speech)) {
    for (int i = 0; i < index->off_cnt; ++i) offsets.push_back(static_cast<SynsetOffset>(index->offset[i]));
    free_index(index);
  }
  (lib.*table).remember(key, offsets);
  return offsets;
}

// The synset at an offset of one part of speech's data file, with its
// pointers of that part of speech, kept in `table`. Takes the lock.
std::optional<Synset> synset_of(SynsetOffset offset, int part_of_speech,
                                util::BoundedTable<SynsetOffset, std::optional<Synset>> Library::*table) {
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  std::optional<Synset> result;
  if (!lib.open) return result;
  if (const auto* kept = (lib.*table).find(offset)) return *kept;
  char empty[1] = {'\0'};
  if (offset >= 0) {
    if (SynsetPtr raw = read_synset(part_of_speech, offset, empty)) {
      Synset s;
      s.offset = offset;
      s.lexicographer_file = raw->fnum;
      for (int i = 0; i < raw->wcount; ++i) s.lemmas.push_back(from_wordnet(raw->words[i]));
      s.gloss = definition_of(raw->defn);
      for (int i = 0; i < raw->ptrcount; ++i) {
        if (raw->ppos[i] != part_of_speech) continue;
        if (raw->ptrtyp[i] == HYPERPTR) s.hypernyms.push_back(raw->ptroff[i]);
        if (raw->ptrtyp[i] == HYPOPTR) s.hyponyms.push_back(raw->ptroff[i]);
        if (raw->ptrtyp[i] == VERBGROUP) s.groups.push_back(raw->ptroff[i]);
      }
      free_synset(raw);
      result = std::move(s);
    }
  }
  (lib.*table).remember(offset, result);
  return result;
}

}  // namespace

std::vector<SynsetOffset> WordNet::noun_senses(std::string_view lemma) const {
  return senses_of(lemma, NOUN, &Library::senses);
}

std::optional<Synset> WordNet::synset(SynsetOffset offset) const { return synset_of(offset, NOUN, &Library::synsets); }

std::vector<SynsetOffset> WordNet::verb_senses(std::string_view lemma) const {
  return senses_of(lemma, VERB, &Library::verb_senses);
}

std::optional<Synset> WordNet::verb_synset(SynsetOffset offset) const {
  return synset_of(offset, VERB, &Library::verb_synsets);
}

namespace {

// Each noun synset's size, from data.noun's pointer fields: a line is
// "offset lex_filenum ss_type w_cnt (word lex_id)* p_cnt (symbol offset pos
// source/target)* ... | gloss", w_cnt in hex; "~" points to a hyponym. The
// synsets come in the order of their offsets, so they are found again by
// binary search.
SynsetSizes read_sizes(const std::string& directory) {
  SynsetSizes out;
  InputLimits limits;  // data.noun is 15 MB, its lines short
  auto read = read_input_file(directory + "/data.noun", limits);
  if (!read) return out;
  const std::string& text = *read;
  std::vector<std::size_t> first_child;  // per synset, into targets
  std::vector<SynsetOffset> targets;
  std::size_t at = 0;
  // The next space-separated field before `end` ("" at the end).
  auto field = [&](std::size_t end) -> std::string_view {
    while (at < end && text[at] == ' ') ++at;
    const std::size_t start = at;
    while (at < end && text[at] != ' ') ++at;
    return std::string_view(text).substr(start, at - start);
  };
  auto number = [](std::string_view f, int base) {
    long value = 0;
    std::from_chars(f.data(), f.data() + f.size(), value, base);
    return value;
  };
  while (at < text.size()) {
    std::size_t line_end = text.find('\n', at);
    if (line_end == std::string::npos) line_end = text.size();
    if (text[at] != ' ') {  // not the licence at the top
      const std::size_t end = std::min(line_end, text.find('|', at));
      out.offsets.push_back(number(field(end), 10));
      first_child.push_back(targets.size());
      field(end);  // lex_filenum
      field(end);  // ss_type
      const long words = number(field(end), 16);
      for (long i = 0; i < 2 * words; ++i) field(end);
      const long pointers = number(field(end), 10);
      for (long i = 0; i < pointers && at < end; ++i) {
        std::string_view symbol = field(end), target = field(end), pos = field(end);
        field(end);  // source/target
        if (symbol == "~" && pos == "n") targets.push_back(number(target, 10));
      }
    }
    at = line_end + 1;
  }
  first_child.push_back(targets.size());
  const std::size_t n = out.offsets.size();
  if (!std::is_sorted(out.offsets.begin(), out.offsets.end())) {
    out.offsets.clear();
    return out;
  }
  // Children as indexes, then sizes bottom-up by a depth-first walk.
  std::vector<std::size_t> children(targets.size());
  for (std::size_t t = 0; t < targets.size(); ++t)
    children[t] = static_cast<std::size_t>(std::lower_bound(out.offsets.begin(), out.offsets.end(), targets[t]) -
                                           out.offsets.begin());
  out.sizes.assign(n, 0);
  std::vector<std::pair<std::size_t, std::size_t>> stack;  // synset, next child
  for (std::size_t root = 0; root < n; ++root) {
    if (out.sizes[root] != 0) continue;
    stack.push_back({root, first_child[root]});
    out.sizes[root] = -1;  // on the stack
    while (!stack.empty()) {
      auto& [synset, next] = stack.back();
      if (next < first_child[synset + 1]) {
        const std::size_t child = children[next++];
        if (child < n && out.sizes[child] == 0) {
          out.sizes[child] = -1;
          stack.push_back({child, first_child[child]});
        }
        continue;
      }
      int size = 1;
      for (std::size_t c = first_child[synset]; c < first_child[synset + 1]; ++c)
        if (children[c] < n && out.sizes[children[c]] > 0) size += out.sizes[children[c]];
      out.sizes[synset] = size;
      stack.pop_back();
    }
  }
  return out;
}

}  // namespace

int WordNet::class_size(SynsetOffset offset) const {
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  if (!lib.open) return 0;
  if (!lib.sizes_built) {
    const char* directory = SetSearchdir();
    lib.sizes = read_sizes(directory ? directory : "");
    lib.sizes_built = true;
    spdlog::debug("wordnet: class sizes of {} noun synsets from {}", lib.sizes.offsets.size(), directory ? directory : "?");
  }
  const std::vector<SynsetOffset>& offsets = lib.sizes.offsets;
  auto found = std::lower_bound(offsets.begin(), offsets.end(), offset);
  if (found == offsets.end() || *found != offset) return 0;
  return std::max(lib.sizes.sizes[static_cast<std::size_t>(found - offsets.begin())], 1);
}

bool WordNet::has_noun(std::string_view lemma) const { return !noun_senses(lemma).empty(); }

bool WordNet::has_verb(std::string_view lemma) const {
  if (!usable(lemma)) return false;
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  if (!lib.open) return false;
  if (const bool* kept = lib.verbs.find(lemma)) return *kept;
  CString query(lemma);
  IndexPtr index = index_lookup(query.text, VERB);
  if (index != nullptr) free_index(index);
  lib.verbs.remember(std::string(lemma), index != nullptr);
  return index != nullptr;
}

namespace {

// Whether the library finds the word under any part of speech, directly or
// through morphology. Under the lock.
bool look_up_anywhere(std::string_view word) {
  for (int pos = NOUN; pos <= ADV; ++pos) {
    CString query(word);
    if (IndexPtr index = index_lookup(query.text, pos)) {
      free_index(index);
      return true;
    }
    CString again(word);
    if (morphstr(again.text, pos) != nullptr) {
      while (morphstr(nullptr, pos) != nullptr) {
      }
      return true;
    }
  }
  return false;
}

}  // namespace

bool WordNet::knows(std::string_view word) const {
  if (!usable(word)) return false;
  Library& lib = library();
  std::lock_guard lock(lib.mutex);
  if (!lib.open) return false;
  if (const bool* kept = lib.known.find(word)) return *kept;
  const bool found = look_up_anywhere(word);
  lib.known.remember(std::string(word), found);
  return found;
}

}  // namespace apprentice::language
