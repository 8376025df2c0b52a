MODULE Prog
  ! Sub may end the cycle: main starts again with count as it was, so the division by
  ! zero comes in the fourth cycle although count := 0 follows the call.
  VAR signaldi diNext;
  VAR num count := 0;
  VAR num ratio := 0;
  PROC main()
    AliasIO "DI_NEXT", diNext;
    count := count + 1;
    IF count > 3 ratio := 1 / 0;
    Sub;
    count := 0;
  ENDPROC
  PROC Sub()
    IF diNext = 1 ExitCycle;
  ENDPROC
ENDMODULE
