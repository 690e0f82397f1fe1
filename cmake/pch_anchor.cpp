int shapecorr_pch_anchor() { return 0; }
