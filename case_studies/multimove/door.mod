MODULE DoorPlant
    ! Environment model of the cell door (give it to `rapidmc check` with
    ! --env).  rapidmc runs react() after every step of the controller.  An
    ! operator may open or close the door at any time while it is unlocked;
    ! a locked door stays as it is.  The door starts closed.
    VAR signaldi diDoorOpen;    ! 1 = the door is open (an input of the PLC task)
    VAR signaldo doDoorLock;    ! 1 = the PLC task keeps the door locked

    PROC react()
        IF DOutput(doDoorLock) = 0 THEN
            SetDI diDoorOpen, AnyNum(0, 1);
        ENDIF
    ENDPROC
ENDMODULE
