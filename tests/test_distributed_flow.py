"""The leader's calls of an eager search without lock-step (``flow.Flow``), with workers
that answer only when the test lets them: calls in flight, batches passed on in order,
and the end of the search only once nothing is in flight, pending or left."""
from rapidmc.check.distributed.flow import IN_FLIGHT, Flow
from rapidmc.check.distributed.rounds import FOUND, HOLDS_ALL, RUNNING


def figures(stored=1, left=0, pieces=(0, 0), failed=-1):
    """A ``flow`` call's figures (``Partition._eager_round``)."""
    return (stored, 0, failed, 0, 0, -1, False, left, list(pieces), 1e-4)


class Leader:
    """The leader's own partition: answers at once, as ``partition._Here`` does."""

    def __init__(self, answers):
        self.answers, self.asked = list(answers), []
        self.call = self

    def options(self, num_returns):
        return self

    def remote(self, _part, method, seconds, senders, *batches):
        self.asked.append((senders, batches))
        batches, found = self.answers.pop(0)
        return (*batches, found)


class Peer:
    """Another worker: each call answers with tokens, ready once the test releases them."""

    def __init__(self):
        self.asked, self.call = [], self

    def options(self, num_returns):
        return self

    def remote(self, _part, method, seconds, senders, *batches):
        self.asked.append((senders, batches))
        return [("batch", len(self.asked), 0), ("batch", len(self.asked), 1),
                ("figures", len(self.asked))]


def _flow(peer, leader, answers, released):
    return Flow([leader, peer], {0}, lambda items: [answers.get(i, i) for i in items],
                lambda refs, wait: [ref for ref in refs if ref in released], None, False)


def test_a_worker_gets_its_next_call_while_stepping_and_the_search_ends_when_all_is_done():
    peer, released, answers = Peer(), set(), {}
    leader = Leader([((None, ["to peer"]), figures(pieces=(0, 1)))])
    flow = _flow(peer, leader, answers, released)
    flow.begin(b"initial")
    assert flow.run(0.0)["outcome"] == RUNNING           # the peer has not answered
    assert flow.run(0.0)["outcome"] == RUNNING
    # the initial states went to both; the leader's batch follows in a second call while
    # the first is in flight, not after it
    assert [senders for senders, _ in peer.asked] == [[-1], [0]] and IN_FLIGHT == 2
    assert peer.asked[1][1] == (["to peer"],)
    assert leader.asked == [([-1], (b"initial",))]
    answers[("figures", 1)] = figures(left=3)
    released.add(("figures", 1))
    # it has states left: a next call queued behind the one in flight, with nothing sent
    assert flow.run(0.0)["outcome"] == RUNNING
    assert len(peer.asked) == 3 and peer.asked[2] == ([], ())
    answers[("figures", 2)] = figures(stored=2, left=1)
    answers[("figures", 3)] = figures(stored=3, left=0)
    released.update((("figures", 2), ("figures", 3)))
    end = flow.run(1.0)
    assert end["outcome"] == HOLDS_ALL and end["stored"] == [1, 3]
    assert len(peer.asked) == 3 and len(leader.asked) == 1


def test_the_state_a_worker_marks_ends_the_search_after_the_calls_in_flight():
    peer, released, answers = Peer(), set(), {}
    leader = Leader([((None, ["to peer"]), figures(pieces=(0, 1)))])
    flow = _flow(peer, leader, answers, released)
    flow.begin(b"initial")
    flow.run(0.0)
    flow.run(0.0)                                        # two calls in flight
    answers[("figures", 1)] = figures(failed=7)
    answers[("figures", 2)] = figures(stored=5)
    released.add(("figures", 1))
    end = flow.run(1.0)
    assert end["outcome"] == FOUND and end["target"] == (1, 7)
    assert not any(flow.calls) and end["stored"] == [1, 5]    # the second call drained
