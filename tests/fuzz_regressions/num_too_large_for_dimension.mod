! expect: exit 2 [RMC209]
! An array dimension beyond the num range is a bad declaration, not an internal error.
MODULE HugeDimension
  VAR pos track{1E39};
  PROC main()
  ENDPROC
ENDMODULE
