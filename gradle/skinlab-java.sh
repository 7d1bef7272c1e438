# Which Java runs skinlab: the newest JDK >= 17 found, or the one the user names.
#
# One POSIX sh fragment with two users: the unix start script of installDist (which
# gradle/skinlab-java.gradle writes this file into) and `gradle :desktop:run` (which runs it with
# sh). It only defines functions and variables named skinlab_*; skinlab_choose_java decides.
#
# The rule (README, "Which Java runs skinlab"):
#   SKINLAB_JAVA_HOME=DIR    the JDK in DIR;
#   SKINLAB_JAVA_HOME=build  the default java, no search: what the start script would run anyway
#                            (JAVA_HOME, else java on the PATH), Gradle's own JVM for `run`;
#   unset or empty           the newest JDK >= 17 among JAVA_HOME, the default java and the folders
#                            that SKINLAB_JAVA_SEARCH matches (colon-separated glob patterns,
#                            default: skinlab_java_search_default below).
# The version is read from the JDK's `release` file (every JDK since 9 has one). A JDK other than
# the default is taken only if it starts with skinlab's JVM options (`java OPTIONS -version`: one
# JVM start, none when the newest is the default itself); a found one that does not is passed
# over in silence, a named one with one line on stderr. The default java itself is never probed:
# if it cannot start, the start script fails as it always did.

skinlab_java_search_default() {
    printf '%s' "/usr/lib/jvm/*:/usr/java/*:/usr/local/lib/jvm/*:/opt/java/*:/opt/jdk*:${HOME:-/nonexistent}/.sdkman/candidates/java/*:${HOME:-/nonexistent}/.jdks/*:/Library/Java/JavaVirtualMachines/*/Contents/Home"
}

# The JVM options a version needs beyond the fixed ones: the one table of them.
# JDK 24 prints warnings on stderr when code on the class path loads a native library (JEP 472;
# LWJGL, for assimp) or calls sun.misc.Unsafe's memory methods (JEP 498; JOML and LWJGL). skinlab
# depends on both libraries, so it grants both. Older JDKs get neither: 17-23 do not warn, and
# 17-22 do not know the second option.
skinlab_java_version_options() {
    if [ "$1" -ge 24 ]; then
        skinlab_java_options='--enable-native-access=ALL-UNNAMED --sun-misc-unsafe-memory-access=allow'
    else
        skinlab_java_options=
    fi
}

# skinlab_java_release DIR: JAVA_VERSION of DIR/release into skinlab_release_version, its feature
# number into skinlab_release_feature and an orderable number (feature, interim, update) into
# skinlab_release_key. Fails when DIR has no readable release file with a version.
skinlab_java_release() {
    skinlab_release_version=
    [ -f "$1/release" ] && [ -r "$1/release" ] || return 1
    while IFS='=' read -r skinlab_name skinlab_value || [ -n "$skinlab_name" ]; do
        if [ "$skinlab_name" = JAVA_VERSION ]; then
            skinlab_value=${skinlab_value#\"}
            skinlab_release_version=${skinlab_value%\"}
        fi
    done < "$1/release"
    [ -n "$skinlab_release_version" ] || return 1
    # "25", "25.0.3", "26-ea", "1.8.0_292": up to three leading numbers separated by dots.
    skinlab_rest=$skinlab_release_version
    skinlab_release_key=0
    skinlab_release_feature=
    for skinlab_scale in 1000000 1000 1; do
        skinlab_part=${skinlab_rest%%[!0-9]*}
        skinlab_rest=${skinlab_rest#"$skinlab_part"}
        case $skinlab_rest in
            .*) skinlab_rest=${skinlab_rest#.} ;;
            *) skinlab_rest= ;;
        esac
        # Leading zeros would read as octal in $(( )).
        while [ "${#skinlab_part}" -gt 1 ] && [ "${skinlab_part#0}" != "$skinlab_part" ]; do
            skinlab_part=${skinlab_part#0}
        done
        [ -n "$skinlab_part" ] || skinlab_part=0
        [ "${#skinlab_part}" -le 6 ] || return 1
        [ -n "$skinlab_release_feature" ] || skinlab_release_feature=$skinlab_part
        skinlab_release_key=$((skinlab_release_key + skinlab_part * skinlab_scale))
    done
}

# skinlab_java_home_of JAVA: the JDK folder of a java command (links resolved), or empty.
skinlab_java_home_of() {
    case $1 in
        */*) skinlab_path=$1 ;;
        *) skinlab_path=$(command -v "$1" 2>/dev/null) || skinlab_path= ;;
    esac
    [ -n "$skinlab_path" ] || return 0
    skinlab_path=$(readlink -f "$skinlab_path" 2>/dev/null || printf '%s' "$skinlab_path")
    case $skinlab_path in
        */bin/java) skinlab_real_dir "${skinlab_path%/bin/java}" ;;
    esac
}

# skinlab_real_dir DIR: DIR with links resolved, printed; nothing when it is not a folder.
skinlab_real_dir() {
    (cd -P -- "$1" 2>/dev/null && pwd -P)
}

# skinlab_java_starts DIR OPTIONS...: is DIR a JDK >= 17 whose java starts with these options and
# its version's own? Leaves that version in skinlab_release_* and its options in skinlab_java_options.
skinlab_java_starts() {
    skinlab_home=$1
    shift
    skinlab_java_release "$skinlab_home" && [ "$skinlab_release_feature" -ge 17 ] \
        && [ -x "$skinlab_home/bin/java" ] || return 1
    skinlab_java_version_options "$skinlab_release_feature"
    # The version's options are plain words: split, never globbed.
    # shellcheck disable=SC2086
    "$skinlab_home/bin/java" $skinlab_java_options "$@" -version >/dev/null 2>&1
}

# skinlab_choose_java DEFAULT_JAVA [OPTIONS...]
#   DEFAULT_JAVA  the java command to use when no other JDK is chosen;
#   OPTIONS       the JVM options skinlab always passes, which a chosen JDK must accept.
# Sets skinlab_java_cmd (the java to run), skinlab_java_version (its JAVA_VERSION, empty when
# unknown) and skinlab_java_options (the options for that version). Returns 0 when it chose a JDK
# other than the default (then in skinlab_java_home), 1 when the default java runs.
skinlab_choose_java() {
    skinlab_default=$1
    shift
    skinlab_default_home=$(skinlab_java_home_of "$skinlab_default")
    case ${SKINLAB_JAVA_HOME:-} in
        build)
            ;;
        '')
            skinlab_found=
            skinlab_index=0
            skinlab_search=${SKINLAB_JAVA_SEARCH:-$(skinlab_java_search_default)}
            skinlab_saved_ifs=$IFS
            IFS=:
            # The default first, so that it wins a tie (it needs no probe). The patterns' globs
            # are expanded on purpose (split on newlines only, so folders may contain spaces).
            for skinlab_pattern in "$skinlab_default_home" "${JAVA_HOME:-}" $skinlab_search; do
                IFS='
'
                for skinlab_dir in $skinlab_pattern; do
                    if [ -n "$skinlab_dir" ] && skinlab_java_release "$skinlab_dir" \
                            && [ "$skinlab_release_feature" -ge 17 ] && [ -x "$skinlab_dir/bin/java" ]; then
                        skinlab_index=$((skinlab_index + 1))
                        skinlab_found="$skinlab_found$skinlab_release_key $skinlab_index $skinlab_dir
"
                    fi
                done
            done
            IFS=$skinlab_saved_ifs
            # Newest first; among equal versions, the order above.
            skinlab_found=$(printf '%s' "$skinlab_found" | sort -k1,1nr -k2,2n)
            while read -r skinlab_key skinlab_index skinlab_dir; do
                [ -n "$skinlab_dir" ] || continue
                skinlab_real=$(skinlab_real_dir "$skinlab_dir")
                if [ "$skinlab_real" = "$skinlab_default_home" ]; then
                    break
                fi
                if skinlab_java_starts "$skinlab_dir" "$@"; then
                    skinlab_java_home=$skinlab_dir
                    skinlab_java_cmd=$skinlab_dir/bin/java
                    skinlab_java_version=$skinlab_release_version
                    return 0
                fi
            done <<EOF
$skinlab_found
EOF
            ;;
        *)
            skinlab_dir=${SKINLAB_JAVA_HOME%/}
            if skinlab_java_starts "$skinlab_dir" "$@"; then
                skinlab_java_home=$skinlab_dir
                skinlab_java_cmd=$skinlab_dir/bin/java
                skinlab_java_version=$skinlab_release_version
                return 0
            fi
            echo "skinlab: ignoring SKINLAB_JAVA_HOME=$SKINLAB_JAVA_HOME: no Java 17 or newer there starts with skinlab's JVM options; using $skinlab_default" >&2
            ;;
    esac
    skinlab_java_home=
    skinlab_java_cmd=$skinlab_default
    skinlab_java_version=
    skinlab_java_options=
    if [ -n "$skinlab_default_home" ] && skinlab_java_release "$skinlab_default_home"; then
        skinlab_java_version=$skinlab_release_version
        skinlab_java_version_options "$skinlab_release_feature"
    fi
    return 1
}
