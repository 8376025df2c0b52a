! expect: RMC101 line 4
MODULE m
  PROC main()
    IF a == b THEN
    ENDIF
  ENDPROC
ENDMODULE
