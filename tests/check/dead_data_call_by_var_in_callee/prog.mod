MODULE Prog
  ! Sub calls Show1 by name: the call of Sub reads count, which Show1 names.
  VAR num count := 0;
  VAR num ratio := 0;
  PROC main()
    count := count + 1;
    Sub;
    count := 0;
  ENDPROC
  PROC Sub()
    CallByVar "Show", 1;
  ENDPROC
  PROC Show1()
    IF count = 1 ratio := 1 / 0;
  ENDPROC
ENDMODULE
