MODULE MainModule
  ! Tests: TryInt on integer values (num and dnum) raises no error and leaves them unchanged.
  PROC main()
    VAR num n := 5;
    VAR num neg := -42;
    VAR dnum d := 4294967295;
    TryInt n;
    TryInt neg;
    TryInt d;
    TPWrite "n=" \Num:=n;
    TPWrite "neg=" \Num:=neg;
    TPWrite "d=" \Dnum:=d;
  ENDPROC
ENDMODULE
