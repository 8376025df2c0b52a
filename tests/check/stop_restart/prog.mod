MODULE StopRestart
    ! A fault branch stops the program; the operator may restart it, and the
    ! code after Stop then runs: divides by zero and sets x to 99.
    VAR num x := 0;
    VAR num y := 1;
    PROC main()
        x := 1;
        Stop;
        x := 99;
        y := 1 / (x - 99);
    ENDPROC
ENDMODULE
