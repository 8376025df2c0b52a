MODULE MainModule
  ! Tests: TPWrite \Num writes at most 6 significant digits (as ValToStr: 1.234567 -> 1.23457).
  PROC main()
    TPWrite "a=" \Num:=1.234567;
    TPWrite "pi=" \Num:=3.14159265;
    TPWrite "third=" \Num:=2 / 3;
    TPWrite "b=" \Num:=100.123456;
  ENDPROC
ENDMODULE
