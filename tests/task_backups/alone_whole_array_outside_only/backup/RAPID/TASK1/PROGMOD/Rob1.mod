MODULE Rob1
    ! Written for the test (issue 28): the gantry reports each of its four stations in
    ! stState; the robot stops on an error and starts when all four are ready.
    PERS string stState{4} := ["", "", "", ""];

    PROC main()
        WHILE TRUE DO
            IF stState{1} = "Error" THEN
                Stop;
            ENDIF
            WaitUntil stState = ["Ready", "Ready", "Ready", "Ready"];
            TPWrite "all stations ready";
        ENDWHILE
    ENDPROC
ENDMODULE
