MODULE Rob1
    ! Written for the test (issue 28): the gantry sets each station's code to 1 when the
    ! station is loaded; the robot starts when all eight are.
    PERS num codes{8} := [0, 0, 0, 0, 0, 0, 0, 0];

    PROC main()
        WaitUntil codes = [1, 1, 1, 1, 1, 1, 1, 1];
        TPWrite "all stations loaded";
    ENDPROC
ENDMODULE
