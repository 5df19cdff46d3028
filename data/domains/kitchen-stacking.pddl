; The kitchen of kitchen.pddl, with objects that interact.
;
; Dishes stack: a bowl resting on a plate must be lifted off before the
; plate can move, and a lid on a pot likewise. A stacked item still stands
; on the surface below its stack, so (on bowl1 table1) holds while it rests
; on plate1; stacks exist on surfaces only.
;
; A drawer can sit inside a cupboard: it opens only while the cupboard is
; open, and the cupboard closes only over a closed drawer (one drawer per
; cupboard).
;
; Everything else is the kitchen: one arm, doors opened and closed with an
; empty hand, items picked up from surfaces and receptacles.
(define (domain kitchen-stacking)
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
    (surface ?s - surface-place)
    (stackable ?o - item)                  ; static: it can be stacked and carry a stack
    (stacked ?top - item ?bottom - item)   ; ?top rests directly on ?bottom
    (covered ?o - item)                    ; something rests on it
    (resting ?o - item)                    ; it rests on another item
    (inner ?d - receptacle-place)          ; static: it sits inside another receptacle
    (has-inner ?c - receptacle-place)      ; static: a receptacle sits inside it
    (inside ?d - receptacle-place ?c - receptacle-place))  ; static

  (:action open
    :parameters (?r - receptacle-place)
    :precondition (and (openable ?r) (not (inner ?r)) (closed ?r) (handempty))
    :effect (not (closed ?r)))

  (:action close
    :parameters (?r - receptacle-place)
    :precondition (and (openable ?r) (not (has-inner ?r)) (not (closed ?r)) (handempty))
    :effect (closed ?r))

  (:action open-inner
    :parameters (?d - receptacle-place ?c - receptacle-place)
    :precondition (and (openable ?d) (inside ?d ?c) (closed ?d) (not (closed ?c)) (handempty))
    :effect (not (closed ?d)))

  (:action close-outer
    :parameters (?c - receptacle-place ?d - receptacle-place)
    :precondition (and (openable ?c) (inside ?d ?c) (closed ?d) (not (closed ?c)) (handempty))
    :effect (closed ?c))

  (:action pick-up
    :parameters (?o - item ?s - surface-place)
    :precondition (and (grabbable ?o) (surface ?s) (on ?o ?s) (not (covered ?o)) (not (resting ?o)) (handempty))
    :effect (and (holding ?o) (not (on ?o ?s)) (not (handempty))))

  (:action pick-up-from
    :parameters (?o - item ?r - receptacle-place)
    :precondition (and (grabbable ?o) (receptacle ?r) (in ?o ?r) (not (covered ?o)) (not (closed ?r))
                       (handempty))
    :effect (and (holding ?o) (not (in ?o ?r)) (not (handempty))))

  (:action put-on
    :parameters (?o - item ?s - surface-place)
    :precondition (and (surface ?s) (holding ?o))
    :effect (and (on ?o ?s) (handempty) (not (holding ?o))))

  (:action put-in
    :parameters (?o - item ?r - receptacle-place)
    :precondition (and (receptacle ?r) (holding ?o) (not (closed ?r)))
    :effect (and (in ?o ?r) (handempty) (not (holding ?o))))

  (:action unstack
    :parameters (?top - item ?bottom - item ?s - surface-place)
    :precondition (and (stackable ?top) (stackable ?bottom) (grabbable ?top) (stacked ?top ?bottom)
                       (on ?top ?s) (not (covered ?top)) (handempty))
    :effect (and (holding ?top) (not (stacked ?top ?bottom)) (not (covered ?bottom)) (not (resting ?top))
                 (not (on ?top ?s)) (not (handempty))))

  (:action stack
    :parameters (?top - item ?bottom - item ?s - surface-place)
    :precondition (and (stackable ?top) (stackable ?bottom) (not (= ?top ?bottom)) (holding ?top)
                       (on ?bottom ?s) (not (covered ?bottom)))
    :effect (and (stacked ?top ?bottom) (covered ?bottom) (resting ?top) (on ?top ?s) (handempty)
                 (not (holding ?top)))))
