# docs/figures/performance_scaling.png from performance_scaling.dat (bench/run_scaling.sh):
# simulation wall time and peak memory against frames, one line per team size, log-log.
set terminal pngcairo size 1100,450 font "DejaVu Sans,11"
set output "docs/figures/performance_scaling.png"
set multiplot layout 1,2 title "Decentralized simulation, synthetic trajectory (medians, Release, 2 shared cores)"
set logscale xy
set grid
set key top left
set xlabel "frames"
set format x "10^{%L}"
set ylabel "wall time of the simulation (s)"
dat = "docs/figures/performance_scaling.dat"
plot for [r in "10 100 1000"] dat using 1:($2 == r+0 ? $3 : 1/0) with linespoints lw 2 pt 7 title r." robots", \
     60 with lines dt 2 lc "black" title "target 60 s"
set ylabel "peak memory of the process (MiB)"
plot for [r in "10 100 1000"] dat using 1:($2 == r+0 ? $5 : 1/0) with linespoints lw 2 pt 7 title r." robots", \
     4096 with lines dt 2 lc "black" title "target 4 GiB"
unset multiplot
