! Task 1: procedure calls with arguments and their ends (the machine pushes and pops the
! task's frame): a num argument rounded to single precision (0.1 * n), a bool and a
! string, a call from a FOR loop (the caller's FOR variable kept below the callee), a
! call two deep, RETURN in a procedure; a call whose stack would be full is not reached.
! Python's: a VAR parameter, an optional one, a function's call and return.
MODULE Caller
  VAR num total := 0;
  VAR num n := 0;
  VAR string last := "";
  PERS num phase := 0;
  PROC main()
    WHILE TRUE DO
      n := n MOD 3 + 1;
      add 0.1 * n, phase = 1, "n";
      FOR i FROM 1 TO 2 DO
        twice i + phase;
      ENDFOR
      bump total;
      maybe;
      total := total MOD 4 + half(2 * n);
    ENDWHILE
  ENDPROC

  PROC add(num amount, bool up, string name)
    VAR num scaled := 0;
    scaled := amount * 10;
    IF up THEN
      IF scaled > 2 total := (total + 1) MOD 5;
      RETURN;
    ENDIF
    last := name;
  ENDPROC

  PROC twice(num k)
    add k, FALSE, "k";
    add k + 1, TRUE, "k1";
  ENDPROC

  PROC bump(INOUT num value)
    value := value MOD 3 + 1;
  ENDPROC

  PROC maybe(\num extra)
    IF Present(extra) total := extra;
  ENDPROC

  FUNC num half(num x)
    RETURN x / 2;
  ENDFUNC
ENDMODULE
