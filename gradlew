#!/usr/bin/env bash
# Runs the installed `gradle` with the same arguments, and shows what a reader needs:
#
#  - Gradle's progress lines (task names, downloads, "BUILD SUCCESSFUL") are left out: `--warn` is
#    added unless an argument chooses a log level itself (-q, -w, -i, -d or their long forms) or
#    asks for everything (-Pverbose). Warnings, errors and what the build prints itself (the
#    summary of each test run) stay. On a terminal Gradle's progress bar still shows.
#  - Debian's Gradle 4.4.1 launcher (/usr/bin/gradle) first runs `java --add-opens ... -version`
#    to see whether its JVM takes that option, and lets the probe's three version lines reach
#    stderr before the build starts. Those leading lines (`openjdk version "..."`, `OpenJDK Runtime
#    Environment ...`, `OpenJDK 64-Bit Server VM ...`) are dropped; every other line passes
#    unchanged, at once. Gradle 8's launcher has no such probe.
#  - The exit status is Gradle's, except for `run` (`gradle :desktop:run`): there it is skinlab's
#    own (docs/cli.md, "Exit statuses"), handed over through the file named by
#    SKINLAB_EXIT_STATUS_FILE, so that a status such as 4 (no display) reaches the shell without
#    Gradle's failure banner. Plain `gradle` fails the build with the status in its message.
#
# This is NOT Gradle's wrapper: it downloads nothing and pins no Gradle version; it needs a
# `gradle` on the PATH (Gradle 4.4.1 or 8, see README).
set -u

if ! command -v gradle >/dev/null 2>&1; then
    echo "gradlew: no gradle on the PATH (apt-get install gradle; see README.md)" >&2
    exit 127
fi

level=(--warn)
for arg in "$@"; do
    case "$arg" in
        -q|--quiet|-w|--warn|-i|--info|-d|--debug|-Pverbose|-Pverbose=*) level=() ;;
    esac
done

SKINLAB_EXIT_STATUS_FILE=$(mktemp "${TMPDIR:-/tmp}/skinlab-status.XXXXXX") || exit 1
export SKINLAB_EXIT_STATUS_FILE
trap 'rm -f "$SKINLAB_EXIT_STATUS_FILE"' EXIT

# stdout goes straight through (fd 3); stderr alone runs through the filter.
{
    gradle ${level[@]+"${level[@]}"} "$@" 2>&1 1>&3 3>&- | awk '
        probe < 3 && (/^openjdk version "/ || /^OpenJDK Runtime Environment/ || /^OpenJDK 64-Bit Server VM/) {
            probe++
            next
        }
        { probe = 3; print; fflush() }' 1>&2 3>&-
    status=${PIPESTATUS[0]}
} 3>&1
if [ "$status" = 0 ] && [ -s "$SKINLAB_EXIT_STATUS_FILE" ]; then
    status=$(cat "$SKINLAB_EXIT_STATUS_FILE")
fi
exit "$status"
