#include "language/same_as.h"

#include <algorithm>
#include <array>

#include "language/utterance.h"
#include "util/text.h"

namespace apprentice::language {

namespace {

// Lower case, without the end's punctuation and the politeness around the
// answer: "Ok, socks too please." -> "socks too".
std::string plain_reply(std::string_view reply) {
  std::string said = to_lower(trim(reply));
  auto drop_end = [&] {
    while (!said.empty() && (said.back() == '.' || said.back() == '!' || said.back() == ',' || said.back() == ' '))
      said.pop_back();
  };
  drop_end();
  // "pencils go w/ the markers": shorthand as the reader takes it.
  {
    std::vector<std::string> words = split_words(said);
    expand_shorthand(words);
    said = join(words, " ");
  }
  for (std::string_view polite : {" please", " thanks", " thank you"})
    if (said.ends_with(polite)) said.resize(said.size() - polite.size());
  drop_end();
  for (bool dropped = true; dropped;) {
    dropped = false;
    for (std::string_view lead : {"ok, ", "ok ", "okay, ", "okay ", "oh, ", "oh ", "and ", "please ", "yes, ", "now "})
      if (said.starts_with(lead)) {
        said = std::string(trim(said.substr(lead.size())));
        dropped = true;
      }
  }
  return said;
}

std::string without_article(std::string phrase) {
  for (std::string_view lead : {"those ", "these ", "that ", "this ", "the ", "a ", "an "})
    if (phrase.starts_with(lead)) return phrase.substr(lead.size());
  return phrase;
}

// A phrase for the thing asked about that names no kind: "it", "this one".
bool names_no_kind(std::string_view phrase) {
  return is_one_of(phrase, {"", "it", "this", "that", "this one", "that one", "them", "these", "those", "they",
                            "one", "this too", "these ones", "those ones"});
}

}  // namespace

SameAs read_same_as(std::string_view reply) {
  std::string said = plain_reply(reply);
  std::string other;
  std::string subject;
  // "with the stapler", "in with the pens", "put it with the mugs": where
  // that thing went, said by the thing.
  for (std::string_view lead : {"with ", "in with ", "on with ", "put it with ", "put it in with ", "put them with ",
                                "put them in with ", "in there with "})
    if (said.starts_with(lead)) said = "same place as " + said.substr(lead.size());
  for (std::string_view marker : {"same place as ", "same way as ", "same as ", "just like ", "like ", "where ",
                                  "goes with ", "go with "}) {
    std::size_t at = said.find(marker);
    if (at == std::string::npos) continue;
    other = said.substr(at + marker.size());
    if (marker == "goes with " || marker == "go with ") {
      subject = std::string(trim(said.substr(0, at)));
    } else if (marker == "like " || marker == "just like ") {
      // "leaves go in the trash like the weeds": what goes, before its verb.
      const std::string before = " " + said.substr(0, at);
      for (std::string_view verb : {" goes ", " go ", " belong ", " belongs ", " should ", " need ", " needs "})
        if (std::size_t v = before.find(verb); v != std::string::npos) {
          subject = std::string(trim(std::string_view(before).substr(0, v)));
          break;
        }
    }
    break;
  }
  std::size_t cut = other.size();
  for (std::string_view mark : {",", ";", " and ", " then ", " but "}) cut = std::min(cut, other.find(mark));
  std::string more(trim(std::string_view(other).substr(cut)));
  other.resize(cut);
  for (std::string_view where : {" on ", " in ", " from "})
    if (std::size_t at = other.find(where); at != std::string::npos) other.resize(at);
  for (std::string_view lead : {",", ";", "and ", "then ", "but "})
    if (more.starts_with(lead)) more = std::string(trim(more.substr(lead.size())));
  for (std::string_view tail : {" goes", " go", " went", " did", " does"})
    if (other.size() > tail.size() && other.ends_with(tail)) other.resize(other.size() - tail.size());
  return {without_article(std::move(other)), more, without_article(std::move(subject))};
}

std::optional<std::string> read_same_again(std::string_view reply) {
  std::string said = plain_reply(reply);
  // The whole reply says "the same", and names nothing.
  if (is_one_of(said, {"same", "the same", "same again", "the same again", "same here", "same thing",
                       "the same thing", "same place", "the same place", "same there", "ditto", "likewise", "also",
                       "too", "same as before", "the same as before", "as before", "like before",
                       "same as last time", "same as the last one", "the same as the last one", "like the last one",
                       "same as that one", "there too", "that one too", "this one too", "same for it",
                       "same for this one", "same with this one", "same goes for this one", "that goes there too",
                       "it goes there too", "this goes there too", "put it there too", "there as well"}))
    return std::string();
  // "socks too", "the sock as well", "the socks go there too".
  for (std::string_view tail : {" goes there too", " go there too", " go there as well", " goes there as well",
                                " there too", " too", " as well", " also"}) {
    if (!said.ends_with(tail) || said.size() == tail.size()) continue;
    std::string named(trim(std::string_view(said).substr(0, said.size() - tail.size())));
    for (std::string_view lead : {"put ", "also "})
      if (named.starts_with(lead)) named = named.substr(lead.size());
    named = without_article(std::move(named));
    // At most a kind's name ("soda can", "big glass tumbler"), not a
    // sentence ("put it in the top drawer too" is an ordinary goal).
    if (std::count(named.begin(), named.end(), ' ') > 2) return std::nullopt;
    return names_no_kind(named) ? std::string() : named;
  }
  // "same for the socks", "also the socks".
  for (std::string_view lead : {"same goes for ", "the same for ", "same for ", "same with ", "the same with ",
                                "also "}) {
    if (!said.starts_with(lead)) continue;
    std::string named = without_article(std::string(trim(said.substr(lead.size()))));
    if (std::count(named.begin(), named.end(), ' ') > 2) return std::nullopt;
    return names_no_kind(named) ? std::string() : named;
  }
  return std::nullopt;
}

}  // namespace apprentice::language
