"""apprentice: an agent that learns new tasks online, in one shot, from an
instructor, its own search, an LLM and WordNet.

    import apprentice
    scenario = apprentice.Scenario.load("data/scenarios/tidy-kitchen.yaml")
    results = apprentice.experiment("data/scenarios/tidy-kitchen.yaml", conditions=["inst+search4"])
    agent = apprentice.Agent(scenario)
    report = agent.learn(lambda question: input(question + " "))
    store = apprentice.KnowledgeStore("kitchen.sqlite")

Errors from apprentice raise apprentice.Error, whose `code` says what kind
('not found', 'invalid input', ...). See docs/python.md.
"""

import json as _json
import os as _os

from ._apprentice import (  # noqa: F401  (re-exported)
    Agent,
    ClassRule,
    Error,
    Goal,
    Knowledge,
    KnowledgeStore,
    LearnedSubtask,
    Object,
    Rule,
    Scenario,
    Subtask,
    Task,
    TaskKnowledge,
    __version__,
    condition_names,
    forget_rule,
    interpret,
    paper_row,
    plan,
    question_kinds,
)
from ._apprentice import _experiment_json

__all__ = [
    "Agent", "ClassRule", "Question", "Error", "Goal", "Knowledge", "KnowledgeStore", "LearnedSubtask", "Object", "Rule",
    "Scenario", "Subtask", "Task", "TaskKnowledge", "condition_names", "experiment", "forget_rule", "interpret", "paper_row",
    "plan", "question_kinds",
]


class Question(str):
    """A question the agent asks its instructor: a str, the words a person
    reads, that also says what it is about, so that a program can answer
    from meaning.

    asked: what kind of question it is, in the one vocabulary of
        question_kinds, `interpret(asked=...)` and `apprentice interpret
        --asked`: "task", "task-step", "subtask-end", "goal", "action",
        "yes-no" or "which"; `interpret(scenario, reply, asked=q.asked,
        object=q.object)` reads a reply as the agent would.
    kind: the same as the dialogue names it (and `apprentice serve`'s
        page): "task-name", "task-step", "subtask-step" (about `object`:
        its goal; without one: is the subtask done?), "next-action",
        "confirm-goal", "confirm-action" or "confirm" (yes/no questions: a
        goal or an action proposed, or another, such as "Shall I leave
        them?"), "which".
    task, subtask: "tidy kitchen", "clear", once known ("" before).
    object, category, place: the object of interest ("ketchup1",
        "ketchup") and the id of the place it is on or in now, or None.
    goal: the goal pursued ("next-action") or proposed ("confirm-goal"),
        as PDDL; action: the action proposed ("confirm-action"); or None.
    """

    def __new__(cls, text, kind="", task="", subtask="", object=None, category=None, place=None, goal=None,
                action=None, asked=""):
        self = super().__new__(cls, text)
        self.kind, self.asked, self.task, self.subtask = kind, asked, task, subtask
        self.object, self.category, self.place = object, category, place
        self.goal, self.action = goal, action
        return self

    @property
    def is_yes_no(self):
        return self.kind in ("confirm-goal", "confirm-action", "confirm")


def experiment(scenario_path, conditions=None, llm=None, generalization="full", knowledge_in=None, use_rules=True,
               knowledge_out=None, transcript_dir=None, **options):
    """Runs the paper's experiment: each condition from empty knowledge, with
    the simulated instructor, on a fresh copy of the scenario.

    conditions: names such as "instruction", "inst+search4", "inst+llm";
        None runs every condition of the paper's Table 3 that can run (the
        LLM ones only with an LLM).
    llm: an LLM backend spec ("openai:http://127.0.0.1:8080/v1",
        "replay:FILE", "corpus:FILE", ...); None uses $APPRENTICE_LLM.
    generalization: "full" (ours) or "paper" (the paper's chunks).
    knowledge_in: a knowledge store every condition starts from (a copy).
    knowledge_out: a folder to keep each condition's knowledge in
        (<condition>.sqlite); transcript_dir: a folder for each condition's
        dialogue (<condition>.txt).
    options: as the CLI's flags of the same names: max_reprompts,
        goal_repair, offer_ungrounded, llm_model, llm_api_key,
        llm_timeout_ms, llm_connect_timeout_ms, llm_seed, llm_optional,
        llm_goal_responses; household: the household of knowledge_in
        whose goals and tasks every condition starts from.

    Returns a list with one dict per condition, with the keys that
    `apprentice experiment --json` prints (condition, completion_rate,
    instructions, words, yes_no, relevance, llm_calls, ...).
    """
    if isinstance(conditions, str):
        conditions = [conditions]
    if knowledge_in is not None:
        knowledge_in = _os.fspath(knowledge_in)
    if knowledge_out is not None:
        knowledge_out = _os.fspath(knowledge_out)
    if transcript_dir is not None:
        transcript_dir = _os.fspath(transcript_dir)
    text = _experiment_json(scenario_path, list(conditions or []), llm, generalization, knowledge_in, knowledge_out,
                            transcript_dir, use_rules=use_rules, **options)
    return _json.loads(text)
