MODULE MainModule
  ! Tests: DnumToNum with \Integer accepts an integer value and rejects a fraction with a
  ! recoverable error (error number not asserted).
  PROC main()
    VAR dnum whole := 1234;
    VAR dnum frac := 5.5;
    VAR num n;
    n := DnumToNum(whole \Integer);
    TPWrite "whole=" \Num:=n;
    n := DnumToNum(frac \Integer);
    TPWrite "not reached";
  ERROR
    TPWrite "error for fraction";
  ENDPROC
ENDMODULE
