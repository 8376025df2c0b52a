! Task 2 of the deadlock (see first.mod): a call with an argument, then the wait.
MODULE Second
  PERS bool first_ready := FALSE;
  PERS bool second_ready := FALSE;
  VAR num total := 0;
  PROC main()
    add 2;
    WaitUntil first_ready;
    second_ready := TRUE;
  ENDPROC

  PROC add(num amount)
    total := total + amount;
  ENDPROC
ENDMODULE
