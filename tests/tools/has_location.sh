#!/bin/sh
# Exit 0 when the text on standard input holds a source location with a line number,
# "file:line: " (e.g. "deck.inp:12: *STATIC: ..."); 1 otherwise. A file name alone
# ("deck.inp: ...") is not a location. Used by tests/run_tests.sh for the bad decks.
grep -qE '[^ :]+:[0-9]+: '
