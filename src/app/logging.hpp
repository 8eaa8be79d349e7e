#pragma once
// Where log lines go and how they look. One line per event. On a terminal: coloured levels. Under
// systemd (stderr connected to the journal, $JOURNAL_STREAM): a syslog priority prefix such as "<4>"
// instead of the level word, so `journalctl -p warning` filters and no colour codes reach the journal.
// Anything else (a file, a pipe): plain "level: message". Every line is valid UTF-8 whatever it quotes:
// bytes that are not (a payload from the broker) are written as U+FFFD (util/valid_utf8.hpp).

namespace puddle::app {

enum class LogStyle { Terminal, Journal, Plain };

// Looks at stderr and $JOURNAL_STREAM.
LogStyle detect_log_style();
// Installs the default logger for `style`.
void setup_logging(LogStyle style);

}  // namespace puddle::app
