; The robot's primitives for tidying a kitchen. It has one arm, so it opens
; and closes doors only with an empty hand. STRIPS has no disjunctive
; preconditions, so taking an item from a surface and from a receptacle are
; two schemas (pick-up, pick-up-from), as are placing it onto a surface and
; into a receptacle (put-on, put-in).
(define (domain kitchen)
  (:requirements :strips :typing :negative-preconditions :equality)
  (:types item place - object
          receptacle-place surface-place - place)
  (:predicates
    (on ?o - item ?s - surface-place)
    (in ?o - item ?r - receptacle-place)
    (holding ?o - item)
    (handempty)
    (closed ?r - receptacle-place)
    (grabbable ?o - item)
    (openable ?r - receptacle-place)
    (receptacle ?r - receptacle-place)
    (surface ?s - surface-place))

  (:action open
    :parameters (?r - receptacle-place)
    :precondition (and (openable ?r) (closed ?r) (handempty))
    :effect (not (closed ?r)))

  (:action close
    :parameters (?r - receptacle-place)
    :precondition (and (openable ?r) (not (closed ?r)) (handempty))
    :effect (closed ?r))

  (:action pick-up
    :parameters (?o - item ?s - surface-place)
    :precondition (and (grabbable ?o) (surface ?s) (on ?o ?s) (handempty))
    :effect (and (holding ?o) (not (on ?o ?s)) (not (handempty))))

  (:action pick-up-from
    :parameters (?o - item ?r - receptacle-place)
    :precondition (and (grabbable ?o) (receptacle ?r) (in ?o ?r) (not (closed ?r)) (handempty))
    :effect (and (holding ?o) (not (in ?o ?r)) (not (handempty))))

  (:action put-on
    :parameters (?o - item ?s - surface-place)
    :precondition (and (surface ?s) (holding ?o))
    :effect (and (on ?o ?s) (handempty) (not (holding ?o))))

  (:action put-in
    :parameters (?o - item ?r - receptacle-place)
    :precondition (and (receptacle ?r) (holding ?o) (not (closed ?r)))
    :effect (and (in ?o ?r) (handempty) (not (holding ?o)))))
