! expect: exit 2 [RMC206]
! Nothing tells the type of this aggregate: a type error, not a TypeError.
MODULE NegatedUntyped
  PROC main()
    TPWrite ValToStr(-[1, 2, 3]);
  ENDPROC
ENDMODULE
