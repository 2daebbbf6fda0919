"""Last (files run in name order): every message the tests provoked is in
Python's words, never the command line's (`--flag`), and never cites a
TOML line for a dict."""

from conftest import MESSAGES


def test_no_message_names_a_command_line_flag():
    assert len(MESSAGES) >= 50, len(MESSAGES)
    flags = [m for m in MESSAGES if "--" in m]
    assert not flags, flags[:5]
