"""``make bench``: the issue-10 targets measured against the strongest honest baselines."""
