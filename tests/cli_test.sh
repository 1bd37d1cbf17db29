#!/usr/bin/env bash
# The command line: values, JSON and clear errors with a non-zero exit.
set -u
rocking="$1"
source "$(dirname "$0")/check_lib.sh"
# q2(0.5) = 4.38821872331181020112 (mpmath, eq. 15); eq. 27 at x = 0.7141699131957593 is 2.
check "case 2 at x = 0.5"            "q = 4.388218723"   "$rocking" q --case 2 --x 0.5
check "eq. 27 crosses q = 2"         $'q = 2\n'   "$rocking" q --case 2 --pulses 6 --x 0.7141699131957593
check "json output"                  '"q": 4.38821872331181' "$rocking" q --case 2 --x 0.5 --json
check "custom train equals case 2"   "q = 4.388218723"   "$rocking" q --train 1:1,-0.5:1 --x 0.5
check "response ends at alpha"       $'\n2,1,'   "$rocking" response --case 2 --x 0.5 --steps 4
# Where the one-corner closed form does not hold, response says so beside its numbers.
check "response below onset warns"   "the input does not lift the block" "$rocking" response --case 2 --x 0.5 --q 0.5
check "response past an impact warns" "the block hits the ground before t_fin" "$rocking" response --case 2 --x 0.5 --q 1.5
check "response json validity"       '"rocking_starts": false, "impact_free": false' "$rocking" response --case 2 --x 0.5 --q 0.5 --json
# Issue 31, item 1: at the collapse q theta(t_fin)/alpha is 1 at any x (it printed -593.2, and nan at x = 700).
check "response at x = 15 ends at alpha"  $'\n3,1,'  "$rocking" response --case 4 --x 15 --steps 4
check "response at x = 700 ends at alpha" $'\n2,1,'  "$rocking" response --case 2 --x 700 --steps 4
check_not "response at x = 700: no nan"   "nan" "$rocking" response --case 2 --x 700 --steps 40
check "400 pulses end at alpha"           $'\n400,1,' "$rocking" response --case 1 --pulses 400 --x 2 --steps 4
# Off the collapse q the response leaves the double range: the rows stop there, saying so.
check "response past the double range"    "# rows end before t/to = 0.75" "$rocking" response --case 2 --x 1000 --q 5 --steps 8
check_not "response past the range: no inf" "inf" "$rocking" response --case 2 --x 1000 --q 5 --steps 8
# Item 8: a one-sine pulse above 1e9 times the threshold fell off its closed form (6e-6 at 1e20 g).
check "one-sine too strong is named"      "--ap: must be at most 1e9 times the uplift threshold" "$rocking" simulate --one-sine --ap 1e20 --wp 10 --alpha 0.1 --p 2
status "one-sine too strong exits 2"      2 "$rocking" simulate --one-sine --ap 1e20 --wp 10 --alpha 0.1 --p 2
# A positive amplitude whose PGA overflows read "the PGA must be > 0".
check "an overflowing PGA is named"       "--rd: the PGA it gives, inf g, is outside the range of double" "$rocking" simulate --case 2 --rd 1e300 --x 1e-100 --alpha 0.15 --p 2
check "a negative --rd is named"          "--rd: must be > 0" "$rocking" simulate --case 2 --rd -1 --x 1 --alpha 0.15 --p 2
# Item 2: the flags come from the same evaluation (it said theta went down to -1.84e9 alpha at x = 20).
check "flags at x = 20"                   "impact-free up to t_fin: yes; motion reverses before t_fin: yes; theta passes alpha before t_fin: yes" "$rocking" q --case 2 --x 20
check_not "no impact warning at x = 20"   "hits the ground" "$rocking" q --case 2 --x 20
check "x = 700 lifts the block"           "rocking starts: yes" "$rocking" q --case 2 --x 700
check "passing alpha is a json flag"      '"passes_alpha_before_t_fin": true' "$rocking" q --case 4 --x 15 --json
check "small x: alpha not passed"         '"passes_alpha_before_t_fin": false' "$rocking" q --case 2 --x 1e-8 --json
check "bad x is named"               "--x: 'abc' is not a number" "$rocking" q --case 2 --x abc
check "negative x is refused"        "--x: must be > 0"  "$rocking" q --case 2 --x -1
check "bad case is named"            "--case: must be a whole number from 1 to 5 (got 7)" "$rocking" q --case 7 --x 1
check "impossible train explained"   "cannot bring theta(t_fin) to alpha" "$rocking" q --train 1:1,-5:1 --x 1
check "a pulse too short is refused"  "below 1e-150" "$rocking" q --train 1:1e-160 --x 1
check_not "a pulse too short: no inf" "q = inf" "$rocking" q --train 1:1e-160 --x 1
status "a pulse too short exits 1"    1 "$rocking" q --train 1:1e-300 --x 1
status "bad x exits 2"               2 "$rocking" q --case 2 --x abc
status "unknown option exits 2"      2 "$rocking" q --case 2 --x 1 --frobnicate 3
status "no command exits 2"          2 "$rocking"
check "no command shows the usage"   $'rocking: no command given\nusage: rocking q' "$rocking"
# A usage error is one line and a pointer to the command's own help, not the whole usage after it.
check "usage error points to --help" $'--x: \'abc\' is not a number\nrun \'rocking q --help\' for its usage' "$rocking" q --case 2 --x abc
check "a record command's error points to its help" "run 'rocking record floor --help' for its usage" "$rocking" record floor
check "an unknown command points to the overview" "run 'rocking --help' for the commands" "$rocking" frobnicate
status "help exits 0"                0 "$rocking" help
# Issue 40, item 7: `rocking COMMAND --help` (-h, `rocking help COMMAND`) is that command's help
# alone: its synopsis first, no other command's, and the definitions it relies on.
topics=(q response simulate "record info" "record synth" "record floor" collapse assess spectrum fragility eq27 batch)
takes_block=" simulate collapse assess spectrum fragility eq27 batch "
overview=$("$rocking" --help)
declare -A first_line
for t in "${topics[@]}"; do first_line[$t]=$("$rocking" $t --help 2>&1 | head -1); done
for t in "${topics[@]}"; do
    status "rocking $t --help exits 0" 0 "$rocking" $t --help
    help=$("$rocking" $t --help 2>&1)
    if [[ ${first_line[$t]} == "usage: rocking $t "* ]]; then echo "ok: $t's help starts with its synopsis"
    else echo "FAIL: $t's help starts: ${first_line[$t]}"; fail=1; fi
    if grep -qE "^(usage: |       )rocking $t " <<<"$overview"; then echo "ok: rocking --help lists $t"
    else echo "FAIL: rocking --help does not list $t"; fail=1; fi
    for u in "${topics[@]}"; do
        [[ $u == "$t" ]] && continue
        if [[ $help == *"${first_line[$u]#usage: }"* ]]; then echo "FAIL: $t's help holds $u's synopsis"; fail=1; fi
    done
    if [[ $takes_block == *" $t "* ]]; then
        for term in "alpha = atan(B/H)" "p = sqrt(3 g/(4 R))" "R = sqrt(B^2 + H^2)/2" "q = PGA/(alpha g)" \
                    "Housner's restitution 1 - 1.5 sin^2 alpha" "ESM/ITACA ASCII or PEER AT2"; do
            [[ $help == *"$term"* ]] || { echo "FAIL: $t's help lacks '$term'"; fail=1; }
        done
    fi
    same "rocking help $t is rocking $t --help" <("$rocking" help $t) <(printf '%s\n' "$help")
    same "rocking $t -h is rocking $t --help" <("$rocking" $t -h) <(printf '%s\n' "$help")
done
check "the overview says where the details are" "'rocking COMMAND --help'" "$rocking" --help
check "-h alone is the overview" "usage: rocking q --case I" "$rocking" -h
check "--help anywhere asks for it" "usage: rocking simulate INPUT BLOCK" "$rocking" simulate --case 2 -h
check "simulate's help: --paper" "--paper           the paper's Section 3 setting: restitution 1 and the final-rotation" "$rocking" simulate --help
check "rocking record --help: the three" "rocking record floor --help." "$rocking" record --help
check "an unknown topic is named"    "rocking: no command 'nosuch' (the commands: q, response, simulate, record info" "$rocking" help nosuch
status "and exits 2"                 2 "$rocking" help nosuch
status "an unknown command's --help exits 2" 2 "$rocking" nosuch --help
status "an unknown record command's help exits 2" 2 "$rocking" help record nosuch
check "help -h is the overview"      "usage: rocking q --case I" "$rocking" help -h
# The errors quote the help's synopsis: spectrum's had lost --mark and --floor.
check "a missing FILE quotes the synopsis" "usage: rocking spectrum FILE [--alpha A[,A...]] [--mark BxH[,BxH...]]" "$rocking" spectrum
check "an option before FILE quotes it" "FILE comes first, before '--block': usage: rocking fragility FILE... (--alpha A[,A...] --p P[,P...] | --block BxH[,BxH...])" "$rocking" fragility --block 0.6x4
status "impossible train exits 1"    1 "$rocking" q --train 1:1,-5:1 --x 1
status "good call exits 0"           0 "$rocking" q --case 4 --x 0.3 --json
# simulate: case 2 at Rd = 0.9 keeps theta(t_fin)/alpha = 0.845691936518 (x = 0.5; the jump sum).
check "simulate below collapse"      "theta(t_fin)/alpha = 0.8456919365" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2
check "simulate criterion named"     "no collapse under final-rotation" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --paper
# One model by default (issue 40): Housner's restitution, 1 - 1.5 sin^2 0.15 = 0.966502, and
# overturning with the free rocking after the input; the same run safe under --paper falls.
check "simulate defaults to the physical model" "COLLAPSE under overturning" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2
check "simulate's default restitution is Housner's" "restitution 0.966502" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2
check "--paper is named in the model line" "restitution 1 (--paper: the paper's setting)" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --paper
check "--paper refuses its own settings" "--paper sets restitution 1 and the final-rotation criterion" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --paper --restitution housner
check "simulate json: the preset"    '"preset": "physical"' "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --json
# The block as built: B = 0.6 m, H = 4 m give alpha = atan(0.15) = 0.148889947609 rad,
# R = sqrt(16.36)/2 = 2.022374842 m, p = sqrt(3 g/(4 R)) = 1.907367 rad/s (eqs. 2, 4).
check "a block by its thickness and height" "alpha = atan(B/H) = 0.14889 rad (8.531 deg), R = sqrt(B^2 + H^2)/2 = 2.02237 m, p = sqrt(3 g/(4 R)) = 1.90737 rad/s" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6 --height 4
check "thickness with the half-height" "alpha = atan(B/H) = 0.14889 rad" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6 --half-height 2
check "a block given both ways that agree" "COLLAPSE" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6 --height 4 --alpha 0.1489 --p 1.907
check "a block given both ways that differ" "give alpha = atan(B/H) = 0.14889 rad, but --alpha is 0.2" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6 --height 4 --alpha 0.2
check "a p that differs from the size's" "give p = sqrt(3 g / (4 R)) = 1.90737 rad/s, but --p is 2" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6 --height 4 --p 2
check "a block wider than tall"      "alpha = atan(B/H) = 0.896055 rad is not below pi/4" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 5 --height 4
check "thickness needs a height"     "--thickness B goes with exactly one of --height H and --half-height h" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6
check "simulate json: the block's size" '"given": "dimensions", "thickness": 0.59999999999999998, "height": 4, "R": 2.0223748416156684' "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --thickness 0.6 --height 4 --json
# Case 1 at x = 10 has q = 1.0001: Rd = 0.99 keeps the PGA below alpha g, and the output says why theta stays 0.
check "simulate says the input never lifts" "the input never lifts the block: its peak, 0.099009 g, is at or below the uplift threshold alpha = 0.1 g" "$rocking" simulate --case 1 --x 10 --rd 0.99 --alpha 0.1 --p 2
check "simulate json: never lifts"   '"input_lifts_block": false' "$rocking" simulate --case 1 --x 10 --rd 0.99 --alpha 0.1 --p 2 --json
check "simulate json"                '"collapse_overturning": true' "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --json
check "simulate at collapse"         "COLLAPSE under final-rotation" "$rocking" simulate --case 2 --x 0.5 --rd 1.0001 --alpha 0.15 --p 2 --paper
check "full model needs an ODE solver" "exact solver handles the linearised equation only" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --model full --solver exact
check "simulate geometry required"   "--alpha A goes with exactly one of --p, --half-height and --height" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15
check "simulate block required"      "give the block as --thickness B --height H (m), or as --alpha A" "$rocking" simulate --case 2 --x 0.5 --rd 0.9
# A height whose p = sqrt(3 g / 4 R) overflows: p was inf (assess --json wrote "p": null).
check "a height too small for a double" "block: height is too small for a double" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --height 2.3e-308
status "a height too small exits 2"   2 "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --height 2.3e-308
check "simulate bad solver"          "unknown solver 'rk4'" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver rk4
check "simulate restitution range"   "--restitution: must be in [0, 1] or housner (got 1.5)" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --restitution 1.5
check "collapse rtol range (before reading the file)" "--rtol: must be in [100 eps, 1) = [2.2204460492503131e-14, 1) (got 2)" "$rocking" collapse no-such-file --alpha 0.15 --rtol 2
status "the rtol bound as printed is accepted" 0 "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver rkf78 --rtol 2.2204460492503131e-14
check "x below 1e-150 names --x"      "--x: must be >= 1e-150" "$rocking" q --case 2 --x 1e-300
status "x below 1e-150 exits 2"       2 "$rocking" q --case 2 --x 1e-300
check "an unknown unit names --unit"  "--unit: 'furlong' is not a unit" "$rocking" record info no-such-file --unit furlong
status "an unknown unit exits 2"      2 "$rocking" record info no-such-file --unit furlong
check "FILE after the options is named" "FILE comes first, before '--alpha'" "$rocking" collapse --alpha 0.15 no-such-file
status "FILE after the options exits 2" 2 "$rocking" assess --alpha 0.15 --height 3 no-such-file
# Below 100 eps rounding decides the steps: Bulirsch-Stoer gave up at 1e-17, Dormand-Prince ran over a minute at 1e-30.
check "rtol below 100 eps refused"   "--rtol: must be in [100 eps, 1) = [2.2204460492503131e-14, 1) (got 1e-30)" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-30
status "rtol below 100 eps exits 2"  2 "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-30
status "rtol at 100 eps runs"        0 "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver bulirsch-stoer --rtol 2.3e-14
check "tolerances printed plainly"   "solver: dopri5 (rtol 1e-06, atol 1e-06 alpha = 1.5e-07 rad)" "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5
# --atol in rad, as ode45's AbsTol: it reaches the solver.  At rtol 1e-12 the
# case-2 run keeps theta(t_fin)/alpha = 0.8456919365 (the jump sum, above) with
# the default atol (1e-12 alpha) and with 1e-13 rad, and loses it at 1e-3 rad.
check "atol stated in rad and alpha" "solver: dopri5 (rtol 1e-12, atol 6.66667e-13 alpha = 1e-13 rad)" \
    "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-12 --atol 1e-13
check "a tight atol keeps the answer" "theta(t_fin)/alpha = 0.8456919365" \
    "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-12 --atol 1e-13
check "a loose atol runs" $'atol 0.00666667 alpha = 0.001 rad)\n  theta(t_fin)/alpha = 0.84569' \
    "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-12 --atol 1e-3
check_not "and moves the answer" "theta(t_fin)/alpha = 0.8456919365" \
    "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-12 --atol 1e-3
check "atol in the JSON, in rad" '"rtol": 9.9999999999999998e-13, "atol_rad": 1e-13' \
    "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --rtol 1e-12 --atol 1e-13 --json
check "atol range in rad and alpha" "--atol: must be in [3.3306690738754696e-15, 0.15) rad, [100 eps, 1) alpha at alpha = 0.15 (got 0.2)" \
    "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --solver dopri5 --atol 0.2
status "atol out of range exits 2" 2 "$rocking" collapse no-such-file --alpha 0.15 --atol 1e-20
status "collapse bad restitution exits 2" 2 "$rocking" collapse no-such-file --alpha 0.15 --restitution x
status "simulate bad criterion exits 2" 2 "$rocking" simulate --case 2 --x 0.5 --rd 0.9 --alpha 0.15 --p 2 --criterion soon
# A block past the top when the pulse ends (theta(t_fin) = 2.4 alpha, moving out)
# falls in the free rocking that follows, under either equation.
for model in linearised full; do
    check "past the top falls ($model)" "overturning: collapse" "$rocking" simulate --one-sine --ap 0.45 --wp 6 \
        --alpha 0.1 --p 2 --model $model --criterion overturning
done
out=$(mktemp)
"$rocking" simulate --one-sine --ap 0.45 --wp 6 --alpha 0.15 --p 2 --output "$out" --dt 0.1 >/dev/null
check "simulate writes theta(t)"     "t,theta_over_alpha,omega_over_alpha_p" cat "$out"
"$rocking" simulate --one-sine --ap 0.45 --wp 6 --alpha 0.15 --p 2 --solver rkf78 --rtol 1e-9 --criterion overturning \
    --output "$out" --dt 0.1 >/dev/null
check "theta(t) file states solver and tolerance" $'# solver: rkf78 (rtol 1e-09, atol 1e-09 alpha = 1.5e-10 rad)\n# criterion: overturning' cat "$out"
rm -f "$out"
# simulate --record: a one-column record holding 0.2 g for 1 s (11 samples) drives
# the block from rest as a step: theta/alpha = (a/alpha - 1)(cosh pt - 1) (eq. 3),
# cosh 1 - 1 = 0.5430806348152437 at alpha = 0.1, p = 1; scaled to q = 3 (0.3 g),
# twice that, 1.0861612696304874, past alpha.
step=$(mktemp)
for k in $(seq 11); do echo 0.2; done > "$step"
check "simulate a step record"       "theta(t_fin)/alpha = 0.5430806348" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1
check "simulate a scaled record"     "theta(t_fin)/alpha = 1.08616127" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --q 3
check "scaled record collapses"      "COLLAPSE under final-rotation" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --q 3 --paper
check "record's scale is stated"     "PGA 0.2 g, scaled to 0.3 g" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --q 3
check "record json"                  '"theta_tfin_over_alpha": 0.54308063481524' "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --json
# Scaled to q = 40 (4 g) the block falls within the input: 39 (cosh t - 1) = (pi/2)/alpha
# at t = acosh(1 + 5 pi / 39) = 0.8698344155836817 s; theta(t_fin) is then not a number to print.
check "fall time of a step"          "fell at t = 0.8698344156 s, before t_fin = 1 s" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --q 40
check "fall time in json"            '"t_overturn": 0.86983441558368' "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --q 40 --json
check "no theta(t_fin) after a fall" '"theta_tfin_over_alpha": null' "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --q 40 --json
check "--rd needs a case"            "--rd does not apply to --record" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --rd 0.9
check "one input only"               "give exactly one input" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --case 2
status "one input only exits 2"      2 "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --case 2
check "missing record is named"      "no-such-file: cannot open the file" "$rocking" simulate --record no-such-file --alpha 0.1 --p 1
status "missing record exits 1"      1 "$rocking" simulate --record no-such-file --alpha 0.1 --p 1
# A one-sine pulse 1e20 times slower than the block fell at its rounding's time (35 s, the closed form's 24.4 s).
check "a one-sine far slower than the block is refused" "--wp: must be at least 1e-6 p = 2e-06 rad/s (got 1e-20)" "$rocking" simulate --one-sine --ap 0.45 --wp 1e-20 --alpha 0.15 --p 2
status "a one-sine far slower exits 2" 2 "$rocking" simulate --one-sine --ap 0.45 --wp 1e-20 --alpha 0.15 --p 2
# A time step of 0 read as "not given" (then "1 values, expected 2" at line 1); a negative one was put on line 0.
check "record-dt 0 refused"          "--record-dt: must be > 0 (got 0)" "$rocking" simulate --record "$step" --unit g --record-dt 0 --alpha 0.1 --p 1
status "record-dt 0 exits 2"         2 "$rocking" simulate --record "$step" --unit g --record-dt 0 --alpha 0.1 --p 1
check "record --dt negative refused" "--dt: must be > 0 (got -0.1)" "$rocking" record info "$step" --unit g --dt -0.1
# Extremes: at 1e20 g the step lifts the block at t = 0 and it falls when (a - alpha)(cosh t - 1) = pi/2,
# t = 1.7724538509055160e-10 s (mpmath, 60 digits); the record kernel put it at 0.05 s before 2026-11-21.
check "fall under 1e20 g"            '"t_overturn": 1.77245385090551' "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --pga 1e20 --json
check "bulirsch-stoer's range"       "bulirsch-stoer: p^2 PGA = 1e+100 (rad/s)^2 g is beyond its range" "$rocking" simulate --record "$step" --unit g --record-dt 0.1 --alpha 0.1 --p 1 --pga 1e100 --solver bulirsch-stoer
rm -f "$step"
# A step of max_step_p / p below the resolution of t spun for ever (p = 1e20 rad/s); the
# solver's guard ("no progress", test_dynamics.cpp) now stands behind the command's refusal
# of p t above 1e9, by the options that set it (issue 38).
ramp=$(mktemp)
printf '0\n0.3\n0.5\n' > "$ramp"
check "a step below t's resolution"  "--record-dt 0.01, --p 1e20: p t = 2e+18 (p = 1e+20 rad/s over 0.02 s) exceeds" timeout 60 "$rocking" simulate --record "$ramp" --unit g --record-dt 0.01 --alpha 0.2 --p 1e20
status "a step below t's resolution exits 2" 2 timeout 60 "$rocking" simulate --record "$ramp" --unit g --record-dt 0.01 --alpha 0.2 --p 1e20
rm -f "$ramp"
# records: every file in the shared folder can be assessed (skipped without the folder).
records="$(dirname "$0")/../../shared/records"
if [ -d "$records" ]; then
    for f in "$records"/esm/* "$records"/peer/*; do
        check "assess $(basename "$f")" "q from eq. 27" "$rocking" assess "$f" --alpha 0.15 --height 2
    done
    check "record info names to_11" "to_11" "$rocking" record info "$records/peer/RSN1158_KOCAELI_DZC180.AT2"
    # The Norcia record under alpha = 0.2, p = 2 rad/s, Housner's restitution:
    # the exact solver and GSL rk8pd at rtol 1e-12 agree on the peak rotation
    # to 1e-11 alpha (bench/work_precision.cpp).
    for solver in exact gsl-rk8pd; do
        check "simulate Norcia ($solver)" "max |theta|/alpha during the input = 0.116311830" "$rocking" simulate \
            --record "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.2 --p 2 --restitution housner \
            --solver $solver --rtol 1e-12
    done
    # Restitution 1, alpha just below the PGA (0.300451 g): lifted by 1e-9
    # alpha, the block rocks at that amplitude to the record's end; the run
    # used to stop at 1e6 impacts ("impact cascade did not end", exit 1).
    check "a hairline rocking to the end" "impacts: 1062" "$rocking" simulate \
        --record "$records/esm/IT.NRC..HGE.D.20161026.171036.C.ACC.ASC" --alpha 0.3 --p 0.7 --paper
    check "collapse below uplift says so" "the record never lifts the block at all (PGA 0.359399 g <= the uplift threshold alpha g = 0.5 g)" \
        "$rocking" collapse "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.5
    check "collapse json" '"found": true' "$rocking" collapse "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.15 --json
    # Nothing found: no p and no safe p, rather than "p": 0.
    check "collapse json with nothing found" '"found": false, "p": null, "p_safe": null' \
        "$rocking" collapse "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.5 --json
    # Table 1's search finds the first collapse on its grid, not the smallest (docs/findings.md, T1b).
    check "collapse says its p is not a bound" "Not a bound" \
        "$rocking" collapse "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.15
    check_not "collapse does not claim the smallest p" "the smallest pulsation" \
        "$rocking" collapse "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.15
    check "assess: a height whose p underflows is named" "--height: the block's p" \
        "$rocking" assess "$records/esm/IT.NRC..HGE.D.20160824.013632.C.ACC.ASC" --alpha 0.15 --height 1e308
else
    echo "skipped: record commands (no shared records folder at $records)"
fi
bad=$(mktemp)
printf 'NDATA: 3\nUNITS: cm/s^2\n1\n2\n' > "$bad"
check "broken record is named" "missing header key SAMPLING_INTERVAL_S" "$rocking" record info "$bad"
status "broken record exits 1" 1 "$rocking" record info "$bad"
rm -f "$bad"
# Records at the edges (found 2026-11-21): a sample that overflows once in
# m/s^2 was read as inf (record info printed "PGA = inf"); a record scaled to
# 1e300 g printed its PGA in 300 digits; a record the half-periods cannot be
# measured on, and a folder, were refused without the file's name or as an
# "empty file".
edge=$(mktemp -d)
printf '0 1e308\n0.01 -1e308\n0.02 0\n0.03 0.1\n0.04 0\n' > "$edge/huge.txt"
check "a sample out of range in m/s2 is refused" "huge.txt:1: '1e308' g is out of range for a double in m/s^2" \
    "$rocking" record info "$edge/huge.txt" --unit g
status "and exits 1" 1 "$rocking" assess "$edge/huge.txt" --alpha 0.1 --height 3 --unit g
printf '0 1e300\n0.01 -1e300\n0.02 0\n0.03 0.1\n0.04 0\n' > "$edge/big.txt"
check "a huge PGA prints in exponent form" "PGA = 9.8100e+300 m/s^2 (1.0000e+300 g)" "$rocking" record info "$edge/big.txt" --unit g
printf '0 0\n0.01 0\n0.02 0\n0.03 0\n' > "$edge/zeros.txt"
check "half-periods of a zero record name the file" "zeros.txt: half_periods: the record is identically zero" \
    "$rocking" assess "$edge/zeros.txt" --alpha 0.1 --height 3 --unit g
check "a folder is not a record" "is a folder, not a record file" "$rocking" record info "$edge"
# A record that overturns the block at the search's lowest p (0.3 rad/s): the
# search has no bracket, and used to print that p as "the smallest pulsation"
# and "safe at 0.000000".
{ echo "0 0"; for i in $(seq 1 200); do echo "$i 2"; done; } | awk '{ printf "%.2f %s\n", $1 / 100, $2 }' > "$edge/strong.txt"
check "collapse at the lowest p says so" "strong.txt overturns the block (alpha = 0.1) already at the search's lowest pulsation" \
    "$rocking" collapse "$edge/strong.txt" --alpha 0.1 --unit g
check "and gives the lowest p as a bound" "p <= 0.300000 rad/s: " "$rocking" collapse "$edge/strong.txt" --alpha 0.1 --unit g
check "and its JSON has no safe p" '"p_safe": null, "below_range": true' "$rocking" collapse "$edge/strong.txt" --alpha 0.1 --unit g --json
# The search's description printed rtol by std::to_string, 1e-8 as "0.000000".
check "collapse states its tolerances plainly" "solver dopri5 rtol 1e-08, atol 1e-07 alpha, p scanned" \
    "$rocking" collapse "$edge/strong.txt" --alpha 0.1 --unit g --solver dopri5 --rtol 1e-8 --atol 1e-8 --json
check "and a restitution factor" "restitution 1e-07, criterion" \
    "$rocking" collapse "$edge/strong.txt" --alpha 0.1 --unit g --restitution 1e-7 --json
rm -rf "$edge"
exit $fail
