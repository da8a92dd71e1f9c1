#!/usr/bin/env bash
# Installs headless Chromium from Debian's packages into DIR (default target/chromium), without
# root: the packages are downloaded (`apt-get download`) and unpacked (`dpkg -x`), with the
# shared libraries this machine lacks. Writes DIR/chromium, a launcher that finds them, and
# prints its path. tests/integration/plots.rs runs it on first use.
set -euo pipefail
dir=$(realpath -m "${1:-target/chromium}")
launcher="$dir/chromium"
if [ -x "$launcher" ] && "$launcher" --version > /dev/null 2>&1; then
    echo "$launcher"
    exit 0
fi
mkdir -p "$dir/debs" "$dir/root"
cd "$dir/debs"
# Chromium, and the libraries it links that a minimal Debian lacks (found with ldd).
packages="chromium chromium-common libopenh264-7 libdouble-conversion3 libharfbuzz-subset0 libpulse0
    libflac12 libopus0 libxnvctrl0 libminizip1 libopenjp2-7 libogg0 libsndfile1 libasyncns0 libvorbis0a
    libvorbisenc2 libmpg123-0 libmp3lame0 libatk-bridge2.0-0 libatk1.0-0 libatspi2.0-0 libcups2
    libgbm1 libnss3 libnspr4 libxcomposite1 libxdamage1 libxrandr2 libxkbcommon0 libgtk-3-0 libasound2"
missing=()
for package in $packages; do
    if ! dpkg-query -W -f='${Status}' "$package" 2> /dev/null | grep -q "install ok installed"; then
        missing+=("$package")
    fi
done
download() { apt-get download "${missing[@]}" > /dev/null 2>&1; }
if ! download; then
    # A machine whose package lists were never fetched.
    apt-get update > /dev/null 2>&1 || true
    download || { echo "apt-get download failed for: ${missing[*]}" >&2; exit 1; }
fi
for deb in *.deb; do
    dpkg -x "$deb" "$dir/root"
done
libraries="$dir/root/usr/lib/x86_64-linux-gnu:$dir/root/usr/lib/x86_64-linux-gnu/pulseaudio:$dir/root/lib/x86_64-linux-gnu"
unresolved=$(LD_LIBRARY_PATH="$libraries" ldd "$dir/root/usr/lib/chromium/chromium" | grep "not found" || true)
if [ -n "$unresolved" ]; then
    echo "Chromium still lacks libraries:" >&2
    echo "$unresolved" >&2
    exit 1
fi
cat > "$launcher" <<LAUNCHER
#!/bin/sh
export LD_LIBRARY_PATH="$libraries\${LD_LIBRARY_PATH:+:\$LD_LIBRARY_PATH}"
exec "$dir/root/usr/lib/chromium/chromium" --headless --no-sandbox --disable-gpu --no-first-run "\$@"
LAUNCHER
chmod +x "$launcher"
"$launcher" --version > /dev/null
echo "$launcher"
