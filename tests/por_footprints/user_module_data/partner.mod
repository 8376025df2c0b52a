MODULE Partner
  PROC main()
    reg1 := 2;                           ! LOCAL
  ENDPROC                                ! LOCAL
ENDMODULE
