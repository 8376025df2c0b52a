MODULE MainModule
  ! Tests: Abs returns the absolute value of a num (negative, positive, zero, fraction).
  PROC main()
    TPWrite "a=" \Num:=Abs(-5);
    TPWrite "b=" \Num:=Abs(7);
    TPWrite "c=" \Num:=Abs(0);
    TPWrite "d=" \Num:=Abs(-2.5);
  ENDPROC
ENDMODULE
