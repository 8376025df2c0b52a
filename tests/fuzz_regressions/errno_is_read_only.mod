! expect: exit 2 [RMC207]
! ERRNO is set by the system: assigning it is an error about a read-only name (it was
! reported as "unknown name 'ERRNO'").
MODULE ErrnoReadOnly
  PROC main()
    RAISE 55;
  ERROR
    ERRNO := 1;
    TRYNEXT;
  ENDPROC
ENDMODULE
