MODULE Watcher
    ! Written for the test (issue 28): reads the robot's flag, never writes it.
    PERS bool bDone := TRUE;

    PROC main()
        WaitUntil bDone;
        TPWrite "done";
    ENDPROC
ENDMODULE
