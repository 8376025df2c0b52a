MODULE FailedNotEnded
    ! A certain division by zero: the program stops with an uncaught error.
    VAR num x := 0;

    PROC main()
        x := 1;
        x := x / 0;
        x := 2;
    ENDPROC
ENDMODULE
