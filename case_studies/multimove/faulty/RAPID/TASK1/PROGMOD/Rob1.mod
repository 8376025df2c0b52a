MODULE Rob1
    ! Robot 1 works in the zone it shares with the other robot.  The PLC task
    ! guards the door (req1, grant1); the robots keep each other out of the
    ! zone themselves, with the shared flag zone_busy: wait until it is
    ! down, then raise it.  Those are two steps, and the other robot may run
    ! between them: both see the zone free and both enter.
    PERS bool req1 := FALSE;
    PERS bool grant1 := FALSE;
    PERS bool zone_busy := FALSE;
    CONST robtarget pHome := [[600,-400,500],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];
    CONST robtarget pZone := [[900,0,300],[1,0,0,0],[0,0,0,0],[9E9,9E9,9E9,9E9,9E9,9E9]];

    PROC main()
        WHILE TRUE DO
            req1 := TRUE;
            WaitUntil grant1;
            WaitUntil NOT zone_busy;
            zone_busy := TRUE;
            WorkInZone;
            zone_busy := FALSE;
            req1 := FALSE;
            WaitUntil NOT grant1;
        ENDWHILE
    ENDPROC

    PROC WorkInZone()
        MoveJ pZone, v1000, fine, tool0;
        MoveJ pHome, v1000, fine, tool0;
    ENDPROC
ENDMODULE
