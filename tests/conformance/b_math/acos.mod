MODULE MainModule
  ! Tests: ACos returns degrees in [0, 180].
  PROC main()
    TPWrite "acos0.5=" \Num:=Round(ACos(0.5) \Dec:=3);
    TPWrite "acos0=" \Num:=Round(ACos(0) \Dec:=3);
    TPWrite "acosm1=" \Num:=Round(ACos(-1) \Dec:=3);
    TPWrite "acos1=" \Num:=ACos(1);
  ENDPROC
ENDMODULE
