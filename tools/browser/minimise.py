"""Delta debugging of many disagreements at once: each round removes one chunk of lines
(then of tokens) from every case still shrinking, and all the candidates of a round are
judged in one batch (one Chromium call, one `check` run). A round tries at most
`WINDOW` chunks of a case, moving on through the rest in later rounds, so that a round
stays small; a time budget ends the search with the smallest shaders found so far. A candidate is kept when it
still disagrees in the same direction for the same reason: a false accept keeps the
browser's error (its text without the quoted token), a false reject keeps check's first
rule. Python standard library only.
"""
import time

import mutate
from stage_oracles import browser_class

WINDOW = 24


def direction(verdict):
    if verdict["browser"] is False and verdict["check"] is True:
        return "false-accept"
    if verdict["browser"] is True and verdict["check"] is False:
        return "false-reject"
    return None


def class_key(verdict):
    kind = direction(verdict)
    if kind == "false-accept":
        return kind, browser_class(verdict["browser_log"])
    if kind == "false-reject":
        return kind, verdict["check_first"].split(":", 1)[0]
    return None


class _Case:
    def __init__(self, job, verdict):
        self.job = job
        self.key = class_key(verdict)
        self.verdict = verdict
        self.phase = "lines"
        self.units = job["source"].split("\n")
        self.n = 2
        self.offset = 0  # first chunk this round tries
        self.candidates = []

    def text(self, units):
        return ("\n" if self.phase == "lines" else "").join(units)

    def propose(self):
        if self.phase == "done":
            return []
        size = max(1, len(self.units) // self.n)
        self.candidates = []
        starts = list(range(0, len(self.units), size))[self.offset:self.offset + WINDOW]
        for start in starts:
            rest = self.units[:start] + self.units[start + size:]
            if rest:
                self.candidates.append(rest)
        return [dict(self.job, source=self.text(c)) for c in self.candidates]

    def advance(self, verdicts):
        for units, verdict in zip(self.candidates, verdicts):
            if class_key(verdict) == self.key:
                self.units = units
                self.verdict = verdict
                self.n = max(self.n - 1, 2)
                self.offset = 0
                return
        size = max(1, len(self.units) // self.n)
        if self.offset + WINDOW < len(range(0, len(self.units), size)):
            self.offset += WINDOW
            return
        self.offset = 0
        if self.n < len(self.units):
            self.n = min(self.n * 2, len(self.units))
            return
        if self.phase == "lines":  # on to tokens, whitespace kept inside each token's text
            self.phase = "tokens"
            self.units = _token_units("\n".join(self.units))
            self.n = 2
        else:
            self.phase = "done"

    def result(self):
        return self.text(self.units), self.verdict


def _token_units(text):
    units = []
    for kind, value in mutate.tokenize(text):
        if kind in ("ws", "comment") and units:
            units[-1] += value
        else:
            units.append(value)
    return units


def minimise(oracles, cases, budget_s=600, log=None):
    """cases: [(job, verdict)] -> [(smallest source, its verdict)] in the same order."""
    states = [_Case(job, verdict) for job, verdict in cases]
    deadline = time.time() + budget_s
    round_number = 0
    while time.time() < deadline:
        round_number += 1
        batch, owners = [], []
        for state in states:
            proposed = state.propose()
            batch.extend(proposed)
            owners.append(len(proposed))
        if not batch:
            break
        verdicts = oracles.judge(batch)
        at = 0
        for state, count in zip(states, owners):
            if count or state.phase != "done":
                state.advance(verdicts[at:at + count])
            at += count
        if log:
            log("minimise round %d: %d candidates, %d cases active" %
                (round_number, len(batch), sum(s.phase != "done" for s in states)))
    return [s.result() for s in states]
