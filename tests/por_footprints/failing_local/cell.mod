MODULE Cell
  ! A step that another task waits for, then a division of the task's own data that
  ! fails.  The division is LOCAL, yet it must not run on in the flag's step: the
  ! partner may see the flag (and set seen) before it fails.
  PERS bool flag := FALSE;
  VAR num own := 0;
  VAR num quotient := 0;
  PROC main()
    flag := TRUE;                        ! SHARED
    quotient := 6 DIV own;               ! LOCAL
  ENDPROC
ENDMODULE
