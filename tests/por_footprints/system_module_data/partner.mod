MODULE Partner
  PROC main()
    tool0.tload.mass := 2;               ! SHARED
  ENDPROC                                ! LOCAL
ENDMODULE
