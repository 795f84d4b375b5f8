# The model of bilayer in one picture (README, "The model"): two layers over
# the same Omega, Sigma cutting Omega into Omega- and Omega+, the crack
# gamma_c through both layers, Gamma_D. Drawn with
#   gnuplot -e "out='docs/figures/model.png'" docs/figures/model.gp
set terminal pngcairo size 1250,620 font "DejaVu Sans,13"
if (!exists("out")) { print "usage: gnuplot -e \"out='FILE.png'\" docs/figures/model.gp"; exit status 1 }
set output out
unset border; unset tics; unset key
set size ratio -1
set xrange [-1.6:4.7]; set yrange [-1.75:1.55]
# Layer 2 (v), drawn behind and offset: the same Omega.
dx = 0.55; dy = 0.35
set object 1 polygon from -1+dx,-1+dy to 1+dx,-1+dy to 1+dx,1+dy to -1+dx,1+dy to -1+dx,-1+dy fc rgb "#c9dcf0" fs solid 1.0 border rgb "#3060a0" lw 1.5 behind
# Layer 1 (u) in front.
set object 2 polygon from -1,-1 to 1,-1 to 1,1 to -1,1 to -1,-1 fc rgb "#f3dcb6" fs transparent solid 0.7 border rgb "#a06020" lw 1.5 front
# Sigma on both layers (dashed), the crack gamma_c through both (thick red).
set arrow 1 from -1+dx,dy to 1+dx,dy nohead lw 2 dt 2 lc rgb "#3060a0" back
set arrow 2 from -0.25+dx,dy to 0.45+dx,dy nohead lw 5 lc rgb "#c00000" back
set arrow 3 from -1,0 to 1,0 nohead lw 2 dt 2 lc rgb "black" front
set arrow 4 from -0.25,0 to 0.45,0 nohead lw 5 lc rgb "#c00000" front
# Gamma_D: clamped left and right sides (hatch marks).
do for [i=0:8] { set arrow 10+i from -1,-1+0.25*i to -1.12,-1.1+0.25*i nohead lw 1 front }
do for [i=0:8] { set arrow 30+i from 1,-1+0.25*i to 1.12,-1.1+0.25*i nohead lw 1 front }
set label 1 "Omega+" at -0.55,0.55 front font ",15"
set label 2 "Omega-" at -0.55,-0.55 front font ",15"
set label 3 "Sigma" at -0.95,0.09 front
set label 4 "gamma_c (crack through both layers)" at -0.25,-0.14 front tc rgb "#c00000"
set label 5 "Gamma_D" at -1.55,-1.25 front
set label 6 "Gamma_D" at 1.0,-1.25 front
set label 7 "layer 1: u = (u_1, u_2), in front" at -1.0,-1.45 front tc rgb "#a06020"
set label 8 "layer 2: v = (v_1, v_2), behind, the same Omega" at -1+dx,1.45 front tc rgb "#3060a0"
set label 20 "Both layers cover all of Omega, one on the other." at 1.75,0.95 left
set label 21 "They are glued to each other along Sigma only:" at 1.75,0.7 left
set label 22 "  u = v on Sigma, on both sides (lambda-, lambda+)." at 1.75,0.45 left
set label 23 "Omega- and Omega+ are the two sides of Sigma," at 1.75,0.1 left
set label 24 "not the two layers. Off the crack layer 1 is glued" at 1.75,-0.15 left
set label 25 "across Sigma (mu_g), and so is layer 2; on gamma_c both" at 1.75,-0.4 left
set label 26 "layers are cut and the faces must not penetrate:" at 1.75,-0.65 left
set label 27 "  [u].nu >= 0 (mu_c >= 0, no friction)." at 1.75,-0.9 left
set arrow 50 from 0.75,-0.25 to 0.75,0.25 head filled size 0.06,20 lw 1.5 front
set label 28 "nu" at 0.8,0.22 front
plot NaN
