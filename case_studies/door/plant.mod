MODULE DoorPlant
    ! Environment model of the door cell: the operator and the safety door,
    ! and a standstill monitor that reports robot motion.  The light curtain
    ! (LIGHT_CURTAIN) is not modelled here, so it stays a free input.
    !
    ! rapidmc runs react() to completion after every program step.  It first
    ! reports whether that step moved the robot, then lets the operator act,
    ! so ROBOT_MOVED in a state belongs to the step taken from the state
    ! before, while the door was as that earlier state shows it.

    VAR signaldi DOOR_CLOSED;   ! door switch, 1 = closed
    VAR signaldo DOOR_LOCK;     ! guard locking, 1 = the program holds the door shut
    VAR signaldi ROBOT_MOVED;   ! standstill monitor, 1 = the last step moved the TCP

    VAR pos last_tcp;

    ! The door starts closed (and unlocked); the robot stands still.
    PROC init()
        SetDI DOOR_CLOSED, 1;
        last_tcp := CPos();
    ENDPROC

    PROC react()
        WatchMotion;
        OperateDoor;
    ENDPROC

    PROC WatchMotion()
        IF Distance(CPos(), last_tcp) > 0.5 THEN
            SetDI ROBOT_MOVED, 1;
        ELSE
            SetDI ROBOT_MOVED, 0;
        ENDIF
        last_tcp := CPos();
    ENDPROC

    ! The operator may open the door whenever it is not locked, and may
    ! close it again at any time.  Locking an open door does nothing.
    PROC OperateDoor()
        IF DOOR_CLOSED = 1 THEN
            IF DOutput(DOOR_LOCK) = 0 THEN
                IF AnyBool() THEN
                    SetDI DOOR_CLOSED, 0;
                ENDIF
            ENDIF
        ELSEIF AnyBool() THEN
            SetDI DOOR_CLOSED, 1;
        ENDIF
    ENDPROC
ENDMODULE
