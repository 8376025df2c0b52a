MODULE MainModule
  ! Tests: TPReadNum accepts fractional and negative answers.
  PROC main()
    VAR num a;
    VAR num b;
    TPReadNum a, "First?";
    TPReadNum b, "Second?";
    TPWrite "sum=" \Num:=a + b;
  ENDPROC
ENDMODULE
