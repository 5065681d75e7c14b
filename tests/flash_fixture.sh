#!/usr/bin/env bash
# SPDX-License-Identifier: MIT
# The pack store tests' fixture: two owner key pairs and signed packs in DIR.
#   flash_fixture.sh SEAMWALK_PACK SAMPLES DIR
# old.swpack (teaspoon, version 1), new.swpack (teacup, version 2),
# older.swpack (teaspoon, version 0), stranger.swpack (signed by another
# key), unsigned.swpack; DIR/keys holds the owner's public key, DIR/unit.ini
# a unit config naming it.
set -euo pipefail
pack=$1 samples=$2 dir=$3
rm -rf "$dir" && mkdir -p "$dir"
"$pack" keygen -o "$dir/owner" >/dev/null
"$pack" keygen -o "$dir/stranger" >/dev/null
cp "$dir/owner.pub" "$dir/keys"
# The unit's trust anchor must be root's alone (firmware/store/STORE.md, "Trusted keys").
chmod 644 "$dir/keys" "$dir"/*.pub && chmod go-w "$dir"
# The unit's config, as the service's names its keys.
printf '[pack]\nkeys = %s\n' "$(cd "$dir" && pwd)/keys" >"$dir/unit.ini"
"$pack" build "$samples/teaspoon.txt" -o "$dir/unsigned.swpack" --quiet
"$pack" build "$samples/teacup.txt" -o "$dir/teacup.swpack" --quiet
"$pack" sign "$dir/unsigned.swpack" --key "$dir/owner.key" --version 1 --name spoon-1 -o "$dir/old.swpack" >/dev/null
"$pack" sign "$dir/teacup.swpack" --key "$dir/owner.key" --version 2 --name cup-2 -o "$dir/new.swpack" >/dev/null
"$pack" sign "$dir/unsigned.swpack" --key "$dir/owner.key" --version 0 --name spoon-0 -o "$dir/older.swpack" >/dev/null
"$pack" sign "$dir/teacup.swpack" --key "$dir/stranger.key" --version 3 --name cup-3 -o "$dir/stranger.swpack" >/dev/null
"$pack" verify "$dir/old.swpack" --key "$dir/keys"
"$pack" verify "$dir/new.swpack" --key "$dir/keys"
