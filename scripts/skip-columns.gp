# The share of samples evaluated along each column (scripts/skip-columns.sh draws it from
# retro render --columns' CSV). Variables: term, ext, out (the folder of skip-columns.csv) and
# frame (what was rendered, for the title).
eval('set terminal '.term)
set termoption noenhanced
set encoding utf8
set datafile separator ','
set output out.'/skip-columns.'.ext
set title "Samples the ybuffer kernel evaluates, per screen column\n".frame
set xlabel 'screen column'
set ylabel "share of the column's samples (%)"
set yrange [0:105]
set autoscale xfix
set grid
set key below horizontal
plot out.'/skip-columns.csv' every ::1 using 1:(100.0 * $5 / $2) with lines lw 2 lc rgb '#999999' title 'evaluated without skipping', \
  '' every ::1 using 1:(100.0 * $3 / $2) with lines lw 2 lc rgb '#1f77b4' title 'evaluated with skipping', \
  '' every ::1 using 1:(100.0 * $4 / $2) with lines lw 2 lc rgb '#d62728' title 'painting (either way)'
