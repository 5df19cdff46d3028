// The predicates the program itself relies on, looked up once in the
// domain. A domain that lacks one, or declares it with another arity, is
// refused at load time with a clear error.
#pragma once

#include "util/result.h"
#include "world/domain.h"

namespace apprentice {

struct Vocabulary {
  PredicateId on = 0;          // (on ?o ?s): item on a surface
  PredicateId in = 0;          // (in ?o ?r): item in a receptacle
  PredicateId holding = 0;     // (holding ?o)
  PredicateId handempty = 0;   // (handempty)
  PredicateId closed = 0;      // (closed ?r)
  PredicateId grabbable = 0;   // (grabbable ?o)   static
  PredicateId openable = 0;    // (openable ?r)    static: it has a door or drawer
  PredicateId receptacle = 0;  // (receptacle ?r)  static
  PredicateId surface = 0;     // (surface ?s)     static

  static Result<Vocabulary> resolve(const Domain& domain);
};

}  // namespace apprentice
