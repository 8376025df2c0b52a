MODULE MainModule
  ! Tests: CosDnum takes degrees and computes in double precision.
  PROC main()
    VAR dnum a60 := 60;
    VAR dnum a180 := 180;
    TPWrite "cos60=" \Dnum:=RoundDnum(CosDnum(a60) \Dec:=12);
    TPWrite "cos180=" \Dnum:=RoundDnum(CosDnum(a180) \Dec:=12);
  ENDPROC
ENDMODULE
