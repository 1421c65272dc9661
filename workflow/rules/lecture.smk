# lecture: figures (rules added by the figure work)
