MODULE EndExit
    ! EXIT ends the program: the assignment after it never runs.
    VAR num x := 0;

    PROC main()
        x := 1;
        EXIT;
        x := 99;
    ENDPROC
ENDMODULE
