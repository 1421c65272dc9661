# blinn_1977: figures (rules added by the figure work)
