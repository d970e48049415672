"""Which episode runs where, for the drivers of worker processes and Ray actors.

Every task of the run is one slot. A slot is handed to one worker at a time; its outcome is accepted once;
when a worker dies, the slots it held go back to the front of the queue (up to `max_attempts` plays each,
after which the slot ends as a failure naming why). The drivers land an episode's record in the run
directory only when its outcome is accepted here, so each task lands exactly once.
"""

from __future__ import annotations

from collections import deque
from collections.abc import Hashable

from ewa_mcp.core.taskmodel import Task
from .outcomes import EpisodeOutcome


class Ledger:
    def __init__(self, tasks: list[Task], max_attempts: int = 3):
        self.tasks = tasks
        self.max_attempts = max_attempts
        self.pending: deque[int] = deque(range(len(tasks)))
        self.attempts = [0] * len(tasks)
        self.in_flight: dict[Hashable, set[int]] = {}
        self.outcomes: dict[int, EpisodeOutcome] = {}

    def take(self, worker: Hashable) -> int | None:
        """The next slot for worker to play, or None when none is waiting."""
        if not self.pending:
            return None
        slot = self.pending.popleft()
        self.attempts[slot] += 1
        self.in_flight.setdefault(worker, set()).add(slot)
        return slot

    def held(self, worker: Hashable) -> int:
        return len(self.in_flight.get(worker, ()))

    def finish(self, worker: Hashable, slot: int, outcome: EpisodeOutcome) -> bool:
        """Accept worker's outcome for slot; False (the caller drops the record) if the slot is not the
        worker's to finish: already finished, or taken back when the worker was declared lost."""
        held = self.in_flight.get(worker, set())
        if slot not in held or slot in self.outcomes:
            return False
        held.discard(slot)
        self.outcomes[slot] = outcome
        return True

    def lost(self, worker: Hashable, reason: str) -> list[EpisodeOutcome]:
        """Take back every slot worker held; return the outcomes of slots that ran out of attempts."""
        given_up = []
        for slot in sorted(self.in_flight.pop(worker, set()), reverse=True):
            if slot in self.outcomes:
                continue
            if self.attempts[slot] >= self.max_attempts:
                task = self.tasks[slot]
                outcome = EpisodeOutcome(task_id=task.id, domain=task.domain, episode_id=None,
                                         failure=f"its worker died {self.attempts[slot]} times while playing it "
                                                 f"(last: {reason[:200]})")
                self.outcomes[slot] = outcome
                given_up.append(outcome)
            else:
                self.pending.appendleft(slot)
        return given_up

    def abandon(self, reason: str) -> list[EpisodeOutcome]:
        """No worker is left: every unfinished slot ends as a failure naming reason."""
        for worker in list(self.in_flight):
            self.in_flight.pop(worker)
        given_up = []
        for slot, task in enumerate(self.tasks):
            if slot not in self.outcomes:
                self.outcomes[slot] = EpisodeOutcome(task_id=task.id, domain=task.domain, episode_id=None,
                                                     failure=reason[:300])
                given_up.append(self.outcomes[slot])
        self.pending.clear()
        return given_up

    @property
    def complete(self) -> bool:
        return len(self.outcomes) == len(self.tasks)
