#!/usr/bin/env bash
# Runs the installed `gradle` with the same arguments, exit status and output, minus one thing:
# Debian's Gradle 4.4.1 launcher (/usr/bin/gradle) first runs `java --add-opens ... -version` to
# see whether its JVM takes that option, and lets the probe's three version lines reach stderr
# before the build starts. Those leading lines (`openjdk version "..."`, `OpenJDK Runtime
# Environment ...`, `OpenJDK 64-Bit Server VM ...`) are dropped; every other line passes
# unchanged, at once. Gradle 8's launcher has no such probe, so there this only passes through.
#
# This is NOT Gradle's wrapper: it downloads nothing and pins no Gradle version; it needs a
# `gradle` on the PATH (Gradle 4.4.1 or 8, see README).
set -u

if ! command -v gradle >/dev/null 2>&1; then
    echo "gradlew: no gradle on the PATH (apt-get install gradle; see README.md)" >&2
    exit 127
fi

# stdout goes straight through (fd 3); stderr alone runs through the filter.
{
    gradle "$@" 2>&1 1>&3 3>&- | awk '
        probe < 3 && (/^openjdk version "/ || /^OpenJDK Runtime Environment/ || /^OpenJDK 64-Bit Server VM/) {
            probe++
            next
        }
        { probe = 3; print; fflush() }' 1>&2 3>&-
    status=${PIPESTATUS[0]}
} 3>&1
exit "$status"
