MODULE MainModule
  ! Tests: ClkReset sets a clock to 0; a clock that was never started reads 0.
  PROC main()
    VAR clock c;
    ClkReset c;
    TPWrite "fresh=" \Num:=ClkRead(c);
    ClkStart c;
    WaitTime 1;
    ClkStop c;
    ClkReset c;
    TPWrite "reset=" \Num:=ClkRead(c);
  ENDPROC
ENDMODULE
